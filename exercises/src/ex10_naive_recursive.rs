//! Exercise 10 — naive recursive Monte Carlo with a branching factor.
//!
//! Slides: "Directions at a point" ("Посоките в една точка"), "Recursion"
//! ("Рекурсивност"), "When does the recursion stop?"
//! ("Кога приключва рекурсията?"), "Solving with Monte Carlo" ("Решаване чрез Monte Carlo метод"), "The combinatorial explosion" ("Комбинаторната
//! експлозия").
//!
//! The rendering equation, in this course's direction convention:
//!
//! ```text
//! L_o(x, ω_o) = L_e(x, ω_o) + ∫_Ω f_r(x, ω_i, ω_o) L_i(x, ω_i) cos θ_i dω_i
//! ```
//!
//! with `ω_o` and `ω_i` both pointing away from x (`ω_i` towards where the
//! light comes from) and `cos θ_i = ω_i·n`, the normal `n` taken on the side
//! of `ω_o`. The lecture writes `ω_i` pointing into the surface (the way
//! the light travels), hence its `(−ω_i·n)`: with `ω_i(lecture) = −ω_i`,
//! `(−ω_i(lecture)·n) = ω_i·n` (slide "The lecture's ωᵢ and ours"). The
//! light arriving from `ω_i` is the light leaving the first surface x′ hit
//! by the ray from x in direction `ω_i`:
//! `L_i(x, ω_i) = L_o(x′, −ω_i)`, another instance of the same equation.
//!
//! Task: return the radiance arriving at the origin of `ray` along it — the
//! `L_o` of its first hit, towards the origin — estimating the integral at
//! every hit with N = `branching` random directions, recursively. The
//! slide "Solving with Monte Carlo" gives the estimator of an integral of
//! any `g` over directions: derive yours for the rendering equation — its
//! `g`, the density of your directions, and what stands for `L_i`. A ray
//! that hits nothing brings the environment's radiance.
//!
//! Depth: `max_depth` = D is the largest number of segments (rays) of a
//! path from the camera: D = 1 shows only the emitters seen directly, D = 2
//! direct light; a path bounces at most D − 1 times. `depth` is the number
//! of segments before `ray` (0 for the camera ray). One pixel sample then
//! traces at most 1 + N + … + N^(D−1) = (N^D − 1)/(N − 1) rays.
//!
//! Toolbox: `Scene::intersect` (an `Interaction`: the point, its shading
//! frame `it.frame`, `it.uv`, `it.wo`), `Scene::escaped_radiance`,
//! `Scene::emitted`, `Scene::brdf` and `Brdf::sample` in the local frame
//! (`Frame::to_local`, `Frame::to_world`, `TransportMode::Radiance`; `None`
//! is a draw that carries nothing), `Interaction::spawn_ray` for the next
//! ray. Every random number comes from `sampler`.
//!
//! Receives: the scene, the ray, its depth, D, N, the sampler. Returns: the
//! radiance estimate. `exercises::plug::StudentNaive` renders a picture with
//! it.
//!
//! ---
//!
//! # На български
//!
//! Задача 10 — наивно рекурсивно Monte Carlo с фактор на разклоняване.
//!
//! Слайдове: „Посоките в една точка“, „Рекурсивност“, „Кога приключва
//! рекурсията?“, „Решаване чрез Monte Carlo метод“, „Комбинаторната експлозия“.
//!
//! Транспортното уравнение в конвенцията за посоките на този курс:
//!
//! ```text
//! L_o(x, ω_o) = L_e(x, ω_o) + ∫_Ω f_r(x, ω_i, ω_o) L_i(x, ω_i) cos θ_i dω_i
//! ```
//!
//! където `ω_o` и `ω_i` сочат навън от x (`ω_i` — натам, откъдето идва
//! светлината), а `cos θ_i = ω_i·n`, с нормалата `n` откъм страната на `ω_o`.
//! Лекцията насочва `ω_i` към повърхността (накъдето пътува светлината), оттам
//! и нейното `(−ω_i·n)`: с `ω_i(лекция) = −ω_i` имаме
//! `(−ω_i(лекция)·n) = ω_i·n` (слайдът „ωᵢ в лекцията и при нас“). Светлината,
//! идваща от `ω_i`, е светлината, която напуска първата повърхност x′, ударена
//! от лъча от x в посока `ω_i`: `L_i(x, ω_i) = L_o(x′, −ω_i)`, друг екземпляр
//! на същото уравнение.
//!
//! Задача: върнете radiance, която пристига в началото на `ray` по него — `L_o`
//! на първото му пресичане към началото — като оценявате интеграла във всяко
//! пресичане с N = `branching` случайни посоки, рекурсивно. Слайдът „Решаване
//! чрез Monte Carlo метод“ дава оценката на интеграл на произволна `g` по
//! посоките: изведете своята за транспортното уравнение — нейното `g`,
//! плътността на посоките ви и какво стои вместо `L_i`. Лъч, който не удря
//! нищо, носи radiance на околната среда.
//!
//! Дълбочина: `max_depth` = D е най-големият брой отсечки (лъчи) на път от
//! камерата: при D = 1 се виждат само излъчвателите, видени направо, при D = 2
//! — директното осветление; пътят се отразява най-много D − 1 пъти. `depth` е
//! броят на отсечките преди `ray` (0 за лъча от камерата). Тогава една проба на
//! пиксел трасира най-много 1 + N + … + N^(D−1) = (N^D − 1)/(N − 1) лъча.
//!
//! Инструменти: `Scene::intersect` (`Interaction`: точката, системата ѝ на
//! засенчване `it.frame`, `it.uv`, `it.wo`), `Scene::escaped_radiance`,
//! `Scene::emitted`, `Scene::brdf` и `Brdf::sample` в локалната система
//! (`Frame::to_local`, `Frame::to_world`, `TransportMode::Radiance`; `None` е
//! избор, който не носи нищо), `Interaction::spawn_ray` за следващия лъч. Всяко
//! случайно число идва от `sampler`.
//!
//! Получава: сцената, лъча, дълбочината му, D, N, sampler-а. Връща: оценката на
//! radiance. `exercises::plug::StudentNaive` рендерира картина с нея.

use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The naive recursive estimate of the radiance along `ray`.
///
/// Наивната рекурсивна оценка на radiance по `ray`.
pub fn naive_radiance(
    scene: &Scene,
    ray: &Ray,
    depth: u32,
    max_depth: u32,
    branching: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: intersect, add the emission, recurse N times and average.
    // TODO (бг): пресечете, добавете излъчването, извикайте рекурсията N пъти и осреднете.
    todo!()
}
