//! Exercise 12 — next event estimation: a path tracer that aims at the lights.
//!
//! Slides: "Directions at a point" ("Посоките в една точка"), "Next event
//! estimation" ("Next event estimation"), "From area to solid angle" ("От
//! площ към пространствен ъгъл"), "Finding the light by chance"
//! ("Светлината, намерена случайно"), "The rendering equation: the
//! integral" ("Транспортното уравнение: интегралът"), "Path tracing in
//! outline" ("Принципна схема на path tracing").
//!
//! Instead of waiting for a path to hit a light, aim at it: choose a point
//! y on a light and connect x to it with a shadow ray. The point is drawn
//! with a density per unit *area* of the light, `p_A(y)`; the rendering
//! equation integrates over *directions* at x, so the estimate needs the
//! density per unit solid angle.
//!
//! Part 1: `area_pdf_to_solid_angle(pdf_area, x, y, n_y)`: the density per
//! unit solid angle at x of the direction towards y (normal `n_y`), when y
//! is drawn with density `pdf_area` per unit area; `x ≠ y`. If the light is
//! seen exactly edge-on from x (`n_y ⟂ y − x`) no solid angle corresponds
//! to the area: return 0 (the caller drops a sample of density 0; its
//! `L_e cos θ_y` would be 0 anyway).
//!
//! Part 2: `estimate_direct(scene, it, sampler)`: a one-sample estimate of
//! the direct light reflected at the hit `it` towards `it.wo`, the part of
//! `∫ f_r L_i cos θ_i dω_i` that comes straight from the lights (directions
//! as in exercise 10: `ω_i` from x towards y, `cos θ_i = ω_i·n` with the
//! normal on the side of `ω_o`):
//! - choose a light with `Scene::choose_light` (one random number); it
//!   returns a `LightChoice`: the light and the probability of having chosen
//!   it (`choice.light`, `choice.pmf`);
//! - for a `Light::Area` take a point uniform by area, `AreaShape::sample_area`
//!   (density `1 / AreaShape::area`); the radiance leaving y towards x is
//!   `AreaLight::le` (zero behind a one-sided light);
//! - other lights (point, environment): `Light::sample_li` gives the
//!   direction, the arriving radiance and its density per solid angle;
//! - the BRDF: `Brdf::eval` in the local frame; visibility:
//!   `Scene::unoccluded` with the shadow ray `Interaction::spawn_ray_to`
//!   (towards the environment: `Interaction::spawn_ray`).
//!
//!
//! Part 3: `path_radiance_nee(scene, ray, max_depth, rr_depth, sampler)`:
//! your path tracer of exercise 11 (copy your own loop) with next event
//! estimation. At every vertex the path reaches, before it continues, add
//! one light sample (part 2), weighted by the throughput β there. Now the
//! direct light of a vertex is found by the light sample — so the emission
//! that the *next* ray happens to hit must not be counted again: the path
//! counts `L_e` (and the environment when it escapes) only where no light
//! sample could have found it — the camera ray, and a ray that left a
//! delta (mirror, glass) lobe, at whose vertex `Brdf::eval` is zero so the
//! light sample found nothing (`BrdfSample::is_delta`; `Brdf::is_delta`
//! says it of the whole model). Depth as in exercise 11: with `max_depth`
//! D a path has at most D segments, and a light sample at a vertex is one
//! more segment (D = 2: emitters seen directly plus the light sample at the
//! first hit, the direct light of part 2). Russian roulette as in exercise
//! 11. `exercises::plug::StudentPathTracer` renders it with
//! `StudentRender::PathNee` (`lesson11 render --student -i path-nee`).
//!
//! Receives: densities and points / the scene, a hit, the sampler / the
//! scene, a camera ray, the depths, the sampler.
//! Returns: the solid-angle density / the direct light estimate / the
//! path's radiance estimate.
//!
//! ---
//!
//! # На български
//!
//! Задача 12 — next event estimation: path tracing, който се цели в лампите.
//!
//! Слайдове: „Посоките в една точка“, „Next event estimation“, „От площ към
//! пространствен ъгъл“, „Светлината,
//! намерена случайно“, „Транспортното уравнение: интегралът“, „Принципна схема
//! на path tracing“.
//!
//! Вместо да чакаме пътят да удари лампа, се целим в нея: избираме точка y от
//! лампа и свързваме x с нея с лъч за сянка. Точката се избира с плътност на
//! единица *площ* от лампата, `p_A(y)`; транспортното уравнение интегрира по
//! *посоките* в x, така че оценката има нужда от плътността на единица
//! пространствен ъгъл.
//!
//! Част 1: `area_pdf_to_solid_angle(pdf_area, x, y, n_y)`: плътността на
//! единица пространствен ъгъл в x на посоката към y (с нормала `n_y`), когато y
//! е избрана с плътност `pdf_area` на единица площ; `x ≠ y`. Ако от x лампата
//! се вижда точно в профил (`n_y ⟂ y − x`), на площта не съответства никакъв
//! пространствен ъгъл: върнете 0 (извикващият изхвърля проба с плътност 0;
//! нейното `L_e cos θ_y` и без това би било 0).
//!
//! Част 2: `estimate_direct(scene, it, sampler)`: оценка с една проба на
//! директната светлина, отразена в пресичането `it` към `it.wo` — частта от
//! `∫ f_r L_i cos θ_i dω_i`, която идва направо от лампите (посоките са като в
//! задача 10: `ω_i` от x към y, `cos θ_i = ω_i·n` с нормалата откъм страната на
//! `ω_o`):
//! - изберете лампа със `Scene::choose_light` (едно случайно число); тя връща
//!   `LightChoice`: лампата и вероятността тя да бъде избрана (`choice.light`,
//!   `choice.pmf`);
//! - за `Light::Area` вземете точка, равномерна по площта,
//!   `AreaShape::sample_area` (плътност `1 / AreaShape::area`); radiance, която
//!   напуска y към x, е `AreaLight::le` (нула зад едностранна лампа);
//! - другите лампи (точкова, околна светлина): `Light::sample_li` дава
//!   посоката, пристигащата radiance и плътността ѝ на единица пространствен
//!   ъгъл;
//! - BRDF: `Brdf::eval` в локалната система; видимост: `Scene::unoccluded` с
//!   лъча за сянка `Interaction::spawn_ray_to` (към околната светлина:
//!   `Interaction::spawn_ray`).
//!
//! Част 3: `path_radiance_nee(scene, ray, max_depth, rr_depth, sampler)`:
//! вашият path tracer от задача 11 (копирайте собствения си цикъл) с next event
//! estimation. Във всеки връх, до който стигне пътят, преди да продължи,
//! добавете една проба от лампите (част 2), претеглена с throughput β там. Сега
//! директната светлина на един връх се намира от пробата от лампите — затова
//! излъчването, което *следващият* лъч случайно удари, не бива да се брои пак:
//! пътят брои `L_e` (и околната среда, когато излезе от сцената) само там,
//! където никоя проба от лампите не би могла да го намери — лъчът от камерата и
//! лъч, излязъл от делта лоб (огледало, стъкло), в чийто връх `Brdf::eval` е
//! нула и пробата от лампите не е намерила нищо (`BrdfSample::is_delta`;
//! `Brdf::is_delta` казва същото за целия модел). Дълбочината е като в задача
//! 11: при `max_depth` D пътят има най-много D отсечки, а пробата от лампите
//! във връх е още една отсечка (D = 2: излъчвателите, видени направо, плюс
//! пробата от лампите в първото пресичане — директната светлина от част 2).
//! Руската рулетка е като в задача 11. `exercises::plug::StudentPathTracer` я
//! рендерира със `StudentRender::PathNee`
//! (`lesson11 render --student -i path-nee`).
//!
//! Получава: плътности и точки / сцената, пресичане, sampler-а / сцената, лъч
//! от камерата, дълбочините, sampler-а. Връща: плътността на единица
//! пространствен ъгъл / оценката на директната светлина / оценката на radiance
//! на пътя.

use raytracer::math::{Color, Ray, Vec3A};
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

/// The density per unit solid angle at `x` of the direction towards `y`.
///
/// Плътността на единица пространствен ъгъл в `x` на посоката към `y`.
pub fn area_pdf_to_solid_angle(pdf_area: f32, x: Vec3A, y: Vec3A, n_y: Vec3A) -> f32 {
    // TODO: how large a solid angle does a small patch dA at y cover, seen from x?
    // TODO (бг): колко голям пространствен ъгъл заема малка площадка dA в y, видяна от x?
    todo!()
}

/// One next-event estimate of the direct light at `it`.
///
/// Една оценка (next event estimation) на директната светлина в `it`.
pub fn estimate_direct(scene: &Scene, it: &Interaction, sampler: &mut Sampler) -> Color {
    // TODO: choose a light, a point on it, convert the density, test visibility.
    // TODO (бг): изберете лампа, точка от нея, преобразувайте плътността, проверете видимостта.
    todo!()
}

/// The radiance estimate of one path starting with `ray`, with next event
/// estimation at every vertex.
///
/// Оценката на radiance на един път, който започва с `ray`, с next event
/// estimation във всеки връх.
pub fn path_radiance_nee(
    scene: &Scene,
    ray: Ray,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Color {
    // TODO: your loop of exercise 11, a light sample at each vertex, and emission counted only where no light sample could have found it.
    // TODO (бг): вашият цикъл от задача 11, проба от лампите във всеки връх и излъчване, броено
    // само там, където никоя проба от лампите не би могла да го намери.
    todo!()
}
