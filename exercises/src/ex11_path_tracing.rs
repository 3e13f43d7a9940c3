//! Exercise 11 — the path tracing loop: throughput and Russian roulette.
//!
//! Slides: "Path tracing in outline" ("Принципна схема на path tracing"),
//! "Russian roulette" ("Руска рулетка"), "Path tracing: samples per pixel"
//! ("Path tracing: проби на пиксел").
//!
//! Path tracing follows one random continuation at each hit instead of N:
//! the integral of the rendering equation is estimated with one sample per
//! bounce (the Monte Carlo estimate of the slide "Solving with Monte Carlo"
//! with N = 1), and the weights of all the bounces so far multiply into the
//! path's throughput β. Lights are
//! found only by hitting them: no light sampling here. Conventions as in
//! exercise 10: directions point away from the surface, `cos θ_i = ω_i·n`
//! with the normal on the side of `ω_o`, and D counts the segments of a path.
//!
//! Task: follow one path from the camera ray `ray` and return its radiance
//! estimate: the light emitted towards the camera at every vertex of the
//! path, each weighted by the path's throughput there, plus the
//! environment's radiance if the path escapes.
//! - `max_depth`: `Some(D)`, at most D segments as in exercise 10; `None`:
//!   no limit.
//! - Russian roulette once the path has made `rr_depth` bounces: continue
//!   with a survival probability q of your choice (from β, say) and end the
//!   path otherwise, keeping the estimate unbiased. Every path must end.
//!
//! Toolbox: as in exercise 10. Returns: the path's radiance estimate.
//! `exercises::plug::StudentPathTracer` renders with it
//! (`lesson11 render --student`).
//!
//! ---
//!
//! # На български
//!
//! Задача 11 — цикълът на path tracing: throughput и руска рулетка.
//!
//! Слайдове: „Принципна схема на path tracing“, „Руска рулетка“, „Path tracing:
//! проби на пиксел“.
//!
//! Path tracing следва по едно случайно продължение във всяко пресичане вместо
//! N: интегралът от транспортното уравнение се оценява с една проба на
//! отражение (Monte Carlo оценката от слайда „Решаване чрез Monte Carlo метод“
//! с N = 1), а теглата на всички досегашни отражения се умножават в throughput
//! β на пътя. Лампите се намират само като бъдат ударени: тук няма избор на
//! точки от лампите. Уговорките са като в задача 10: посоките сочат навън от
//! повърхността, `cos θ_i = ω_i·n` с нормалата откъм страната на `ω_o`, а D
//! брои отсечките на пътя.
//!
//! Задача: проследете един път от лъча от камерата `ray` и върнете оценката му
//! на radiance: светлината, излъчена към камерата във всеки връх на пътя, всяка
//! претеглена с throughput на пътя там, плюс radiance на околната среда, ако
//! пътят излезе от сцената.
//! - `max_depth`: `Some(D)` — най-много D отсечки, както в задача 10; `None` —
//!   без ограничение.
//! - Руска рулетка, щом пътят е направил `rr_depth` отражения: продължете с
//!   вероятност за оцеляване q по ваш избор (например от β), а иначе прекратете
//!   пътя, така че оценката да остане неотместена. Всеки път трябва да свърши.
//!
//! Инструменти: както в задача 10. Връща: оценката на radiance на пътя.
//! `exercises::plug::StudentPathTracer` рендерира с нея
//! (`lesson11 render --student`).

use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The radiance estimate of one path starting with `ray`.
///
/// Оценката на radiance на един път, който започва с `ray`.
pub fn path_radiance(
    scene: &Scene,
    ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: a loop, not a recursion: throughput, emission, one BRDF sample, roulette.
    // TODO (бг): цикъл, не рекурсия: throughput, излъчване, една проба от BRDF, рулетка.
    todo!()
}
