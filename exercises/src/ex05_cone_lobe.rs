//! Exercise 5 — normalizing another lobe: a uniform cone.
//!
//! Slides: "BRDF examples" ("Примери за BRDF"), "Properties of BRDFs" ("Свойства на BRDF-ите"), "BRDF examples:
//! a perfect mirror" ("Примери за BRDF: чисто отражение").
//!
//! The lecture normalizes its BRDFs (1/π, `S(n)`) so that they conserve
//! energy. Do it yourself for a lobe the lecture does not show: a "rough
//! mirror" that reflects uniformly into a cone of half-angle θ_m around the
//! mirror direction,
//!
//! ```text
//! f_r(ω_i, ω_o) = ρ · C(θ_m)   if α < θ_m,   0 otherwise,
//! ```
//!
//! α being the angle between `ω_i` and `reflect(ω_o)`, as in exercise 4.
//!
//! Task: derive the constant `C(θ_m)`, in sr⁻¹, that makes the directional
//! albedo `∫_Ω f_r cos θ_i dω_i` exactly ρ at normal incidence (`ω_o = +z`),
//! and return it.
//!
//! Receives: θ_m in radians, `0 < θ_m ≤ π/2`. Returns: `C(θ_m)`.
//!
//! Two checks you can make yourself: at θ_m = π/2 the cone is the whole
//! hemisphere and the lobe must be Lambert's (exercise 3); as θ_m → 0 the
//! lobe narrows to the perfect mirror of exercise 6 and `C` grows without
//! bound — the lecture's "∞" of the mirror.
//!
//! ---
//!
//! # На български
//!
//! Задача 5 — нормиране на друг лоб: равномерен конус.
//!
//! Слайдове: „Примери за BRDF“, „Свойства на BRDF-ите“, „Примери за BRDF: чисто
//! отражение“.
//!
//! Лекцията нормира своите BRDF (1/π, `S(n)`), така че да запазват енергията.
//! Направете го сами за лоб, който лекцията не показва: „грапаво огледало“,
//! което отразява равномерно в конус с полуъгъл θ_m около огледалната посока,
//!
//! ```text
//! f_r(ω_i, ω_o) = ρ · C(θ_m)   ако α < θ_m,   иначе 0,
//! ```
//!
//! където α е ъгълът между `ω_i` и `reflect(ω_o)`, както в задача 4.
//!
//! Задача: изведете константата `C(θ_m)` в sr⁻¹, при която насоченото албедо
//! `∫_Ω f_r cos θ_i dω_i` е точно ρ при перпендикулярно падане (`ω_o = +z`), и
//! я върнете.
//!
//! Получава: θ_m в радиани, `0 < θ_m ≤ π/2`. Връща: `C(θ_m)`.
//!
//! Две проверки, които можете да направите сами: при θ_m = π/2 конусът е цялата
//! полусфера и лобът трябва да е този на Ламберт (задача 3); когато θ_m → 0,
//! лобът се стеснява до идеалното огледало от задача 6 и `C` расте неограничено
//! — „∞“ на огледалото от лекцията.

/// `C(θ_m)`: the normalization of a uniform cone of half-angle `theta_max`.
///
/// `C(θ_m)`: нормировката на равномерен конус с полуъгъл `theta_max`.
pub fn cone_lobe_normalization(theta_max: f32) -> f32 {
    // TODO: the albedo at normal incidence is C times an integral over the cone.
    // TODO (бг): албедото при перпендикулярно падане е C по интеграл по конуса.
    todo!()
}
