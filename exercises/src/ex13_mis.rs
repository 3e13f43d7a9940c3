//! Exercise 13 — multiple importance sampling: a path tracer that uses both strategies.
//!
//! Slides: "Multiple importance sampling" ("Multiple importance sampling"),
//! "Next event estimation" ("Next event estimation"), "Finding the light by
//! chance" ("Светлината, намерена случайно").
//!
//! At every vertex the direct light can be found two ways: by a light
//! sample (exercise 12) and by the BRDF sample that continues the path and
//! happens to hit an emitter (exercise 11). Exercise 12 kept only the first
//! (the second was counted only after a mirror); light sampling alone is
//! noisy where a large light meets a shiny surface, BRDF sampling alone where
//! a small light meets a rough one (Veach's plates, the slide). Here both
//! count, each weighted so that the two weights of one direction sum to
//! one: the power heuristic with exponent 2, as the slide writes it in
//! general and the renderer uses (the balance heuristic, exponent 1, is a valid weight too,
//! but it is not the one asked for, and the grader tells them apart).
//!
//! Task: `path_radiance_mis(scene, ray, max_depth, rr_depth, sampler)`:
//! your path tracer (exercises 11 and 12; copy your own loop) where at every
//! vertex x
//! - one light sample is added with its power-heuristic weight, and
//! - the emitter that the continuation ray hits (an area light, or the
//!   environment when it escapes) is added with its power-heuristic weight.
//!
//! Each weight compares the two densities with which the two strategies
//! would have produced the SAME direction ω_i at x, both per unit solid
//! angle at x, each the density of everything its strategy chose to make
//! that direction. Which two densities these are is yours to work out from
//! the slide's general form. Compute the weights yourself (a small helper
//! function of your own is welcome; not `raytracer::sampling`'s heuristics).
//! Where only one strategy could have made the sample it takes the whole
//! weight: the camera ray; a ray that left a delta lobe (mirror, glass: no
//! light sample finds light there, `Brdf::eval` and `Brdf::pdf` are zero);
//! a point light (`LightSample::is_delta`: no ray ever hits it).
//! Depth and Russian roulette as in exercise 12: with `max_depth` D a path
//! has at most D segments, a light sample adds one.
//!
//! Toolbox (besides exercise 11's):
//! - the light sample: `Scene::choose_light` (its `pmf`), then
//!   `Light::sample_li(x, u)`: the direction `wi`, the arriving radiance
//!   `li`, its density `pdf_w` per unit solid angle, the point `p` and
//!   normal `n` on the light for the shadow ray
//!   (`Interaction::spawn_ray_to(p, n)`, or `Interaction::spawn_ray(wi)` when
//!   `dist` is infinite: the environment), `Scene::unoccluded`;
//! - the BRDF's density of a direction it did not sample: `Brdf::pdf`
//!   (local frame);
//! - an emitter hit by a ray: `Scene::emitter_hit(&ray, hit)`, with the hit
//!   (`None` when the ray escaped): the light's index in `Scene::lights`, the
//!   radiance `le` it sends back, the point `p` and normal `n` where the ray
//!   met it;
//! - the light strategy's density of a direction that happened to hit the
//!   light: `Light::pdf_li_w(x, p, n, wi)` (per unit solid angle at x, for
//!   the same sampling `Light::sample_li` does), and `Scene::light_pmf`.
//!   Take the light sample from `Light::sample_li` too (not exercise 12's
//!   sampling by area): a weight must use the density of the sampling you
//!   actually do, and for a sphere seen from outside `Light::sample_li`
//!   samples the cone it subtends, not its area (Veach's lights are spheres).
//!
//! Receives: the scene, a camera ray, the depths, the sampler. Returns: the
//! path's radiance estimate. `exercises::plug::StudentPathTracer` renders it
//! with `StudentRender::PathMis` (`lesson11 render --student -i path`).
//!
//! ---
//!
//! # На български
//!
//! Задача 13 — multiple importance sampling: path tracing с двете стратегии.
//!
//! Слайдове: „Multiple importance sampling“, „Next event estimation“,
//! „Светлината, намерена случайно“.
//!
//! Във всеки връх директната светлина може да се намери по два начина: с проба
//! от лампите (задача 12) и с пробата от BRDF, която продължава пътя и случайно
//! удря излъчвател (задача 11). Задача 12 запази само първия (вторият се броеше
//! само след огледало); само избор по лампите е шумен там, където голяма лампа
//! среща лъскава повърхност, а само избор по BRDF — там, където малка лампа
//! среща грапава (пластините на Veach, слайдът). Тук се броят и двете, всяка с
//! тегло, избрано така, че двете тегла на една посока да имат сбор единица:
//! степенната евристика (power heuristic) с показател 2, както я записва
//! слайдът в общ вид и както я ползва рендерерът (балансовата евристика, с показател 1,
//! също е валидно тегло, но не тя се иска и проверката ги различава).
//!
//! Задача: `path_radiance_mis(scene, ray, max_depth, rr_depth, sampler)`:
//! вашият path tracer (задачи 11 и 12; копирайте собствения си цикъл), в който
//! във всеки връх x
//! - се добавя една проба от лампите с теглото ѝ по степенната евристика и
//! - излъчвателят, който продължаващият лъч удари (лампа с площ или околната
//!   светлина, когато лъчът излезе от сцената), се добавя с теглото си по
//!   степенната евристика.
//!
//! Всяко тегло сравнява двете плътности, с които двете стратегии биха дали
//! СЪЩАТА посока ω_i в x, и двете на единица пространствен ъгъл в x, всяка —
//! плътността на всичко, което стратегията ѝ е избрала, за да стигне до тази
//! посока. Кои са тези две плътности, изведете сами от общия вид на слайда.
//! Пресметнете теглата сами
//! (малка ваша помощна функция е добре дошла; не евристиките от
//! `raytracer::sampling`). Там, където само едната стратегия би могла да
//! направи пробата, тя взима цялото тегло: лъчът от камерата; лъч, излязъл от
//! делта лоб (огледало, стъкло: там никоя проба от лампите не намира светлина,
//! `Brdf::eval` и `Brdf::pdf` са нула); точкова светлина
//! (`LightSample::is_delta`: никой лъч не я удря). Дълбочината и руската
//! рулетка са като в задача 12: при `max_depth` D пътят има най-много D
//! отсечки, а пробата от лампите добавя една.
//!
//! Инструменти (освен тези от задача 11):
//! - пробата от лампите: `Scene::choose_light` (с нейното `pmf`), после
//!   `Light::sample_li(x, u)`: посоката `wi`, пристигащата radiance `li`,
//!   плътността ѝ `pdf_w` на единица пространствен ъгъл, точката `p` и
//!   нормалата `n` върху лампата за лъча за сянка
//!   (`Interaction::spawn_ray_to(p, n)` или `Interaction::spawn_ray(wi)`,
//!   когато `dist` е безкрайно: околната светлина), `Scene::unoccluded`;
//! - плътността на BRDF за посока, която тя не е избрала: `Brdf::pdf` (локална
//!   система);
//! - излъчвател, ударен от лъч: `Scene::emitter_hit(&ray, hit)` с пресичането
//!   (`None`, когато лъчът е излязъл от сцената): индексът на лампата в
//!   `Scene::lights`, radiance `le`, която тя изпраща обратно, точката `p` и
//!   нормалата `n`, където лъчът я е срещнал;
//! - плътността на стратегията с лампите за посока, която случайно е ударила
//!   лампата: `Light::pdf_li_w(x, p, n, wi)` (на единица пространствен ъгъл в
//!   x, за същия избор, който прави `Light::sample_li`), и `Scene::light_pmf`.
//!   Вземайте и пробата от лампите от `Light::sample_li` (не избора по площ от
//!   задача 12): теглото трябва да ползва плътността на избора, който наистина
//!   правите, а за сфера, видяна отвън, `Light::sample_li` избира в конуса,
//!   който тя заема, а не по площта ѝ (лампите на Veach са сфери).
//!
//! Получава: сцената, лъч от камерата, дълбочините, sampler-а. Връща: оценката
//! на radiance на пътя. `exercises::plug::StudentPathTracer` я рендерира със
//! `StudentRender::PathMis` (`lesson11 render --student -i path`).

use raytracer::math::{Color, Ray};
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// The radiance estimate of one path starting with `ray`: light sampling and
/// BRDF sampling at every vertex, combined by the power heuristic.
///
/// Оценката на radiance на един път, който започва с `ray`: избор по лампите и
/// избор по BRDF във всеки връх, съчетани чрез степенната евристика.
pub fn path_radiance_mis(
    scene: &Scene,
    ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: your loop of exercise 12, with both strategies counted at every vertex, each with its power-heuristic weight.
    // TODO (бг): вашият цикъл от задача 12, с двете стратегии, броени във всеки връх, всяка с
    // теглото си по степенната евристика.
    todo!()
}
