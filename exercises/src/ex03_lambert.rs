//! Exercise 3 — the Lambertian BRDF with a texture.
//!
//! Slides: "BRDF examples" ("Примери за BRDF"), "Properties of BRDFs"
//! ("Свойства на BRDF-ите"), "Question: which constant for Lambert?"
//! ("Въпрос: каква е константата на Lambert?"), "BRDFs: a little more
//! complex" ("BRDF-и: малко по-сложно").
//!
//! A diffuse (Lambertian) surface reflects the same radiance in every
//! direction: its BRDF is a constant for every pair of directions. How large
//! a constant is fixed by energy conservation, and with a diffuse texture it
//! depends on the point, through the texture's colour there.
//!
//! A BRDF is a density per unit solid angle (sr⁻¹), not a probability: its
//! values may exceed 1 (a narrow glossy lobe's do). What is bounded is the
//! directional albedo `∫_Ω f_r cos θ_i dω_i ≤ 1`, the fraction of the light
//! arriving from all directions that leaves towards `ω_o`. (The slide writes
//! the bound over ω_o, `∫ f_r cos Θ_o dω_o ≤ 1`; by reciprocity,
//! `f_r(ω_i, ω_o) = f_r(ω_o, ω_i)`, it is the same integral.)
//!
//! Task: evaluate the Lambertian BRDF whose directional albedo is the
//! texture `albedo` at the texture coordinates `uv`: a white texture
//! (albedo 1) reflects exactly all the light, `∫_Ω f_r cos θ_i dω_i = 1`
//! over the hemisphere, and a texel of colour ρ reflects the fraction ρ of
//! it, channel by channel. Derive the constant from that integral.
//! Directions are in the local shading frame: the normal is `+z`, so
//! `cos θ` of a direction is its `z`; `wo` points towards
//! the viewer, `wi` towards where the light comes from (both away from the
//! surface). Light from below, or leaving below (`wi.z ≤ 0` or `wo.z ≤ 0`),
//! is not reflected: return black.
//!
//! Receives: the albedo texture (its colour at `uv` is `Texture::eval`),
//! `uv`, `wo`, `wi`. Returns: `f_r` alone — the cosine of the rendering
//! equation belongs to the integrator, not here.
//!
//! ---
//!
//! # На български
//!
//! Задача 3 — ламбертовата BRDF с текстура.
//!
//! Слайдове: „Примери за BRDF“, „Свойства на BRDF-ите“, „Въпрос: каква е
//! константата на Lambert?“, „BRDF-и: малко по-сложно“.
//!
//! Дифузната (ламбертова) повърхност отразява една и съща radiance във всяка
//! посока: BRDF ѝ е константа за всяка двойка посоки. Колко голяма е
//! константата, определя запазването на енергията, а при дифузна текстура тя
//! зависи от точката чрез цвета на текстурата там.
//!
//! BRDF е плътност на единица пространствен ъгъл (sr⁻¹), не вероятност:
//! стойностите ѝ може да надхвърлят 1 (тези на тесен glossy лоб го правят).
//! Ограничено е насоченото албедо `∫_Ω f_r cos θ_i dω_i ≤ 1` — частта от
//! светлината, идваща от всички посоки, която излиза към `ω_o`. (Слайдът
//! записва ограничението по ω_o, `∫ f_r cos Θ_o dω_o ≤ 1`; по симетричността
//! `f_r(ω_i, ω_o) = f_r(ω_o, ω_i)` това е същият интеграл.)
//!
//! Задача: пресметнете ламбертовата BRDF, чието насочено албедо е текстурата
//! `albedo` в текстурните координати `uv`: бяла текстура (албедо 1) отразява
//! точно цялата светлина, `∫_Ω f_r cos θ_i dω_i = 1` по полусферата, а тексел
//! с цвят ρ отразява частта ρ от нея, за всеки канал поотделно. Изведете
//! константата от този интеграл. Посоките са в локалната система на
//! засенчването: нормалата е `+z`, така че `cos θ` на една посока е нейното
//! `z`; `wo` сочи към
//! наблюдателя, `wi` — натам, откъдето идва светлината (и двете навън от
//! повърхността). Светлина, която идва отдолу или излиза отдолу (`wi.z ≤ 0` или
//! `wo.z ≤ 0`), не се отразява: върнете черно.
//!
//! Получава: текстурата на албедото (цветът ѝ в `uv` е `Texture::eval`), `uv`,
//! `wo`, `wi`. Връща: само `f_r` — косинусът от транспортното уравнение е
//! работа на интегратора, не тук.

use raytracer::brdf::Texture;
use raytracer::math::{Color, Vec2, Vec3A};

/// `f_r(ω_i, ω_o)` of a textured Lambertian surface.
///
/// `f_r(ω_i, ω_o)` на ламбертова повърхност с текстура.
pub fn lambert_eval(albedo: &Texture, uv: Vec2, wo: Vec3A, wi: Vec3A) -> Color {
    // TODO: f_r at uv, from the albedo the texture gives there and energy conservation.
    // TODO (бг): f_r в uv, от албедото, което текстурата дава там, и запазването на енергията.
    todo!()
}
