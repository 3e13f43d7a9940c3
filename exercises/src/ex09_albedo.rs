//! Exercise 9 — a Monte Carlo estimate of the directional albedo.
//!
//! Slides: "Properties of BRDFs" ("Свойства на BRDF-ите"), "Solving with
//! Monte Carlo" ("Решаване чрез Monte Carlo метод").
//!
//! Energy conservation: a surface reflects at most the light it receives.
//! The slide writes it as `∫_Ω f_r(ω_i, ω_o) cos Θ_o dω_o ≤ 1`: the light
//! arriving from one direction ω_i, reflected into all directions ω_o. Here
//! we compute the directional albedo
//!
//! ```text
//! ρ(ω_o) = ∫_Ω f_r(ω_i, ω_o) cos θ_i dω_i,
//! ```
//!
//! the light arriving from all directions ω_i, reflected towards one ω_o.
//! By reciprocity (the slide's symmetry, `f_r(ω_i, ω_o) = f_r(ω_o, ω_i)`)
//! the two integrals are the same function of the one fixed direction, so
//! either form of the bound says the same.
//!
//! Task: estimate `ρ(ω_o)` of `brdf` for `wo` (local frame, normal `+z`) by
//! the Monte Carlo method with N = `samples` random directions. The slide
//! "Solving with Monte Carlo" estimates an integral of any `g` over
//! directions; which `g` and which density are yours to write down, for
//! the sampling you choose. Draw the directions as you like:
//! - with the BRDF's own sampling, `Brdf::sample` (it returns a
//!   `BrdfSample` with `wi`, `f` and `pdf_w`, or `None` when the direction
//!   it drew carries nothing, e.g. below the horizon: such a draw
//!   contributes 0 and is still one of the N);
//! - or uniformly or cosine-weighted over the hemisphere
//!   (`raytracer::sampling::warp`), with `Brdf::eval`.
//!
//! Take every random number from `sampler` (`Sampler::next_1d`,
//! `Sampler::next_2d`); use `uv = Vec2::ZERO` and `TransportMode::Radiance`.
//!
//! Receives: the BRDF, `wo`, the sampler, N. Returns: the estimate (RGB).
//! The grader calls it many times with independent samplers and compares
//! the mean of your estimates with the exact albedo, using the spread of
//! your own estimates. One case is a Phong lobe seen at 75° from the normal,
//! whose albedo is well below ρ_s (exercise 4).
//!
//! ---
//!
//! # На български
//!
//! Задача 9 — Monte Carlo оценка на насоченото албедо.
//!
//! Слайдове: „Свойства на BRDF-ите“, „Решаване чрез Monte Carlo метод“.
//!
//! Запазване на енергията: повърхността отразява най-много толкова светлина,
//! колкото получава. Слайдът го записва като
//! `∫_Ω f_r(ω_i, ω_o) cos Θ_o dω_o ≤ 1`: светлината, дошла от една посока ω_i,
//! отразена във всички посоки ω_o. Тук пресмятаме насоченото албедо
//!
//! ```text
//! ρ(ω_o) = ∫_Ω f_r(ω_i, ω_o) cos θ_i dω_i,
//! ```
//!
//! светлината, дошла от всички посоки ω_i, отразена към една посока ω_o. По
//! симетричността (реципрочността от слайда, `f_r(ω_i, ω_o) = f_r(ω_o, ω_i)`)
//! двата интеграла са една и съща функция на единствената фиксирана посока,
//! така че двата записа на ограничението казват едно и също.
//!
//! Задача: оценете `ρ(ω_o)` на `brdf` за `wo` (локална система, нормала `+z`)
//! по метода Monte Carlo с N = `samples` случайни посоки. Слайдът „Решаване
//! чрез Monte Carlo метод“ оценява интеграл на произволна `g` по посоките;
//! коя е `g` и с каква плътност, изведете сами за избора, който правите.
//! Избирайте посоките както искате:
//! - с избора по самата BRDF, `Brdf::sample` (връща `BrdfSample` с `wi`, `f` и
//!   `pdf_w` или `None`, когато избраната посока не носи нищо, например под
//!   хоризонта: такъв избор допринася 0 и пак е един от N-те);
//! - или равномерно, или с тегло косинус по полусферата
//!   (`raytracer::sampling::warp`), с `Brdf::eval`.
//!
//! Вземайте всяко случайно число от `sampler` (`Sampler::next_1d`,
//! `Sampler::next_2d`); ползвайте `uv = Vec2::ZERO` и
//! `TransportMode::Radiance`.
//!
//! Получава: BRDF, `wo`, sampler-а, N. Връща: оценката (RGB). Проверката я вика
//! много пъти с независими sampler-и и сравнява средното на вашите оценки с
//! точното албедо, като използва разсейването на собствените ви оценки. Един от
//! случаите е лоб на Phong, видян под 75° от нормалата, чието албедо е доста
//! под ρ_s (задача 4).

use raytracer::brdf::Brdf;
use raytracer::math::{Color, Vec3A};
use raytracer::sampling::Sampler;

/// A Monte Carlo estimate of `∫ f_r cos θ_i dω_i` for `wo`.
///
/// Monte Carlo оценка на `∫ f_r cos θ_i dω_i` за `wo`.
pub fn estimate_albedo(brdf: &Brdf, wo: Vec3A, sampler: &mut Sampler, samples: u32) -> Color {
    // TODO: average the contributions of `samples` random directions.
    // TODO (бг): осреднете приносите на `samples` случайни посоки.
    todo!()
}
