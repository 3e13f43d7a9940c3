//! Exercise 6 — the perfect mirror, a delta BRDF.
//!
//! Slides: "BRDF examples: a perfect mirror" ("Примери за BRDF: чисто отражение").
//!
//! The lecture writes the mirror's BRDF as ∞ where `ω_o = reflect(ω_i)` and
//! 0 elsewhere: no function one could evaluate; only sampling finds the
//! mirror direction. Exactly, it is a distribution,
//! `f_r(ω_i, ω_o) = R · δ(ω_i − reflect(ω_o)) / cos θ_i` with δ the Dirac
//! delta over solid angle, such that the reflected radiance
//! `∫ f_r L_i cos θ_i dω_i` is `R · L_i(reflect(ω_o))`.
//!
//! Part 1: `reflect(w, n)`: the mirror direction of the unit vector `w`
//! about the unit normal `n` (world space). `w`, `n` and the result lie in
//! one plane, the result makes the same angle with `n` as `w`, and both
//! point away from the surface.
//!
//! Part 2: `mirror_sample(reflectance, wo)`: the BRDF sample of a mirror in
//! the local frame (normal `+z`), in the form every BRDF of the renderer
//! returns (`BrdfSample`: the direction `wi`, the value `f`, `pdf_w`,
//! `is_delta`, and `eta` = 1 for reflection). The path tracer weights every
//! sample by `f · |cos θ_i| / pdf_w`. For a delta lobe `pdf_w` is not a
//! density over directions (a delta has none) but the probability with
//! which the sampler chose that lobe among the BRDF's lobes; a mirror has a
//! single lobe. Derive `f` so that the weight is what the delta gives in the
//! reflected radiance `∫ f_r L_i cos θ_i dω_i`. If `wo.z ≤ 0` there is no
//! reflected direction above the surface (at `wo.z = 0` it lies in the
//! surface, where `cos θ_i = 0`): return `None`.
//!
//! Receives: `w`, `n` / the reflectance `R` and `wo`. Returns: the reflected
//! direction / the sample.
//!
//! ---
//!
//! # На български
//!
//! Задача 6 — идеалното огледало, делта BRDF.
//!
//! Слайд: „Примери за BRDF: чисто отражение“.
//!
//! Лекцията записва BRDF на огледалото като ∞ там, където `ω_o = reflect(ω_i)`,
//! и 0 другаде: това не е функция, която може да се пресметне; огледалната
//! посока се намира само чрез избор на посока. Точно казано, това е
//! разпределение, `f_r(ω_i, ω_o) = R · δ(ω_i − reflect(ω_o)) / cos θ_i`, където
//! δ е делта функцията на Дирак по пространствения ъгъл, такова, че отразената
//! radiance `∫ f_r L_i cos θ_i dω_i` е `R · L_i(reflect(ω_o))`.
//!
//! Част 1: `reflect(w, n)`: огледалната посока на единичния вектор `w` спрямо
//! единичната нормала `n` (в световни координати). `w`, `n` и резултатът лежат
//! в една равнина, резултатът сключва с `n` същия ъгъл като `w` и двата сочат
//! навън от повърхността.
//!
//! Част 2: `mirror_sample(reflectance, wo)`: пробата на огледалото в локалната
//! система (нормала `+z`), във вида, в който я връща всяка BRDF на рендерера
//! (`BrdfSample`: посоката `wi`, стойността `f`, `pdf_w`, `is_delta` и `eta` =
//! 1 за отражение). Path tracing претегля всяка проба с
//! `f · |cos θ_i| / pdf_w`. При делта лоб `pdf_w` не е плътност по посоките
//! (делтата няма такава), а вероятността, с която е избран този лоб измежду
//! лобовете на BRDF; огледалото има един-единствен лоб. Изведете `f` така, че
//! теглото да е това, което делтата дава в отразената radiance
//! `∫ f_r L_i cos θ_i dω_i`. Ако `wo.z ≤ 0`, над повърхността няма отразена
//! посока (при `wo.z = 0` тя лежи в повърхността, където `cos θ_i = 0`):
//! върнете `None`.
//!
//! Получава: `w`, `n` / отражателната способност `R` и `wo`. Връща: отразената
//! посока / пробата.

use raytracer::brdf::BrdfSample;
use raytracer::math::{Color, Vec3A};

/// The mirror direction of `w` about `n`.
///
/// Огледалната посока на `w` спрямо `n`.
pub fn reflect(w: Vec3A, n: Vec3A) -> Vec3A {
    // TODO: draw w, n and the result; which component of w stays?
    // TODO (бг): начертайте w, n и резултата; коя компонента на w остава?
    todo!()
}

/// The one sample of a perfect mirror (`None` if `wo.z ≤ 0`).
///
/// Единствената проба на идеалното огледало (`None`, ако `wo.z ≤ 0`).
pub fn mirror_sample(reflectance: Color, wo: Vec3A) -> Option<BrdfSample> {
    // TODO: wi, then pdf_w and f such that the path tracer's weight is what the delta gives.
    // TODO (бг): wi, после pdf_w и f такива, че теглото в path tracing да е това, което дава
    // делтата.
    todo!()
}
