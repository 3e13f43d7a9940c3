//! Exercise 4 — the normalized Phong lobe.
//!
//! Slides: "BRDF examples" ("Примери за BRDF"), "Properties of BRDFs" ("Свойства на BRDF-ите").
//!
//! The lecture's glossy BRDF is `f_r = S(n) · max(0, cos∠(reflect(ω_i),
//! ω_o))^n`, with `S(n)` "a normalizing constant meant to conserve energy".
//! Directions point away from the surface (`ω_o` towards the viewer, `ω_i`
//! towards the light), and `reflect(ω)` mirrors a direction about the normal
//! (slide "Directions at a point"; exercise 6 derives its formula). A reflection keeps angles and is its own inverse, so
//! the slide's angle between `reflect(ω_i)` and `ω_o` is the angle α between
//! `ω_i` and `reflect(ω_o)`. We add the specular albedo ρ_s as a factor.
//!
//! Part 1: `phong_normalization(n)` returns the `S(n)` that makes the
//! directional albedo `∫_Ω f_r cos θ_i dω_i` of the lobe with ρ_s = 1
//! exactly 1 at normal incidence (`ω_o = +z`, the normal). At other angles
//! part of the lobe falls below the horizon and the albedo is less than ρ_s
//! (exercise 9 measures it at 75°): `S(n)` keeps the energy exactly only at
//! normal incidence, and below it elsewhere.
//!
//! Part 2: `phong_eval(albedo, n, wo, wi)` returns `f_r = ρ_s · S(n) ·
//! max(0, cos α)^n` in the local frame (normal `+z`); both directions lie in
//! the upper hemisphere (the renderer checks that).
//!
//! `f_r` is a density in sr⁻¹, not a probability: at the centre of the lobe
//! it is ρ_s·S(n), far above 1 for a narrow lobe.
//!
//! Receives: the exponent `n`, any real `n ≥ 0` (not only integers), and
//! ρ_s, `wo`, `wi`. Returns: `S(n)`, and `f_r`.
//!
//! ---
//!
//! # На български
//!
//! Задача 4 — нормираният лоб на Phong.
//!
//! Слайдове: „Примери за BRDF“, „Свойства на BRDF-ите“.
//!
//! Glossy BRDF от лекцията е `f_r = S(n) · max(0, cos∠(reflect(ω_i), ω_o))^n`,
//! където `S(n)` е „нормираща константа, целяща запазване на енергията“.
//! Посоките сочат навън от повърхността (`ω_o` към наблюдателя, `ω_i` към
//! светлината), а `reflect(ω)` отразява посоката огледално спрямо нормалата
//! (слайдът „Посоките в една точка“; формулата ѝ извежда задача 6). Отражението запазва ъглите и е обратно само на себе си, така че
//! ъгълът от слайда между `reflect(ω_i)` и `ω_o` е ъгълът α между `ω_i` и
//! `reflect(ω_o)`. Добавяме и огледалното албедо ρ_s като множител.
//!
//! Част 1: `phong_normalization(n)` връща онова `S(n)`, при което насоченото
//! албедо `∫_Ω f_r cos θ_i dω_i` на лоба с ρ_s = 1 е точно 1 при
//! перпендикулярно падане (`ω_o = +z`, нормалата). Под други ъгли част от лоба
//! попада под хоризонта и албедото е по-малко от ρ_s (задача 9 го мери при
//! 75°): `S(n)` запазва енергията изцяло само при перпендикулярно падане, а
//! другаде — не цялата.
//!
//! Част 2: `phong_eval(albedo, n, wo, wi)` връща
//! `f_r = ρ_s · S(n) · max(0, cos α)^n` в локалната система (нормала `+z`); и
//! двете посоки са в горната полусфера (рендерерът проверява това).
//!
//! `f_r` е плътност в sr⁻¹, не вероятност: в центъра на лоба тя е ρ_s·S(n),
//! далеч над 1 за тесен лоб.
//!
//! Получава: експонентата `n`, всяко реално `n ≥ 0` (не само цели), и ρ_s,
//! `wo`, `wi`. Връща: `S(n)` и `f_r`.

use raytracer::math::{Color, Vec3A};

/// `S(n)`: the normalization of the Phong lobe `cos^n α`.
///
/// `S(n)`: нормировката на лоба на Phong `cos^n α`.
pub fn phong_normalization(n: f32) -> f32 {
    // TODO: the albedo at normal incidence is S(n) times an integral; make it 1.
    // TODO (бг): албедото при перпендикулярно падане е S(n) по един интеграл; направете го 1.
    todo!()
}

/// `f_r(ω_i, ω_o) = ρ_s · S(n) · max(0, cos α)^n`.
///
/// Стойността на лоба `f_r(ω_i, ω_o) = ρ_s · S(n) · max(0, cos α)^n`.
pub fn phong_eval(albedo: Color, n: f32, wo: Vec3A, wi: Vec3A) -> Color {
    // TODO: α is measured from the mirror direction of wo.
    // TODO (бг): α се мери от огледалната посока на wo.
    todo!()
}
