//! Exercise 14 — a light tracer: light paths joined to the camera.
//!
//! Slides: "Light tracing" ("Light tracing"), "The connection to the camera"
//! ("Свързването с камерата"), "What a path brings" ("Какво носи един път").
//!
//! Light tracing is path tracing run backwards: a path starts on a light,
//! bounces through the scene by BRDF sampling, and every vertex it makes is
//! joined to the camera's lens. Such a connection makes a whole path from
//! the lens to the light: one sample of the integral over paths (slides "The
//! integral over paths", "What a path brings"), whose Monte Carlo estimate
//! `C` you derive (slide "The connection to the camera"). It lands on the
//! pixel where the camera sees the vertex, as a *splat*. The
//! camera's importance `W_e` plays the role `L_e` plays for lights. This is
//! how the caustic of the `caustic` scene is found — a path tracer would
//! have to hit a point light after a refraction.
//!
//! Task: trace ONE light path and push the splat of every vertex that the
//! camera sees onto `splats`. Everything you find goes to the film as
//! splats (the integrator around you returns 0 for the pixel sample); the
//! film scales a pixel's splats by `W·H / M` (M pixel samples in all), so a
//! splat's value is the estimate `C` of one path, nothing more.
//!
//! 1. **Start on a light**: choose one with `Scene::choose_light` (it gives
//!    `P(light)`, `LightChoice::pmf`), and emit a ray from it with
//!    `Light::sample_le` (an `Emission`: the point `p` on the light, its
//!    normal `n`, the emitted `le` along the ray, the density `pdf_a` of the
//!    point per unit area and `pdf_w` of the direction per unit solid
//!    angle). Skip the environment (`Light::is_environment`): it has no light
//!    paths here. The path's throughput β as it leaves the light is its
//!    Monte Carlo weight so far: what it carries of the light's emission,
//!    for everything chosen so far. `L_e` is radiance: per unit projected
//!    area and per unit solid angle. A point light
//!    (`is_delta_position`) has no surface: its `n` is zero, its cosine
//!    counts as 1, and its `le` is its intensity.
//! 2. **The light seen directly**: join the light's point `y_0` to the lens
//!    too: a path of one segment, whose value holds the light's `L_e`
//!    towards the lens (`Scene::emitted_by` with the light's
//!    `LightChoice::index`) and for which only the light and the point on it
//!    were chosen. A pinhole cannot be hit by a light path, so this is the
//!    only way the camera sees an area light.
//! 3. **At every surface the path hits** (`Scene::intersect`), unless its BRDF
//!    is a delta (`Brdf::is_delta`: mirror, glass — joining those to the lens
//!    has zero value), join the vertex to the lens:
//!    - a lens point: `plug::sample_lens` (a `LensPoint` with its
//!      density `pdf_a` per unit area of the lens; the lens faces
//!      `Camera::forward`);
//!    - where it lands: `Camera::raster_of` (world → raster), `None` where the
//!      camera cannot see the vertex (behind the lens, outside the film);
//!    - the importance `W_e`: `Camera::we` of the ray from the lens point
//!      towards the vertex;
//!    - the geometry term of the connection, with the cosine at the vertex
//!      taken with the shading normal `it.frame.n` (a light path may reach a
//!      surface from behind: what counts is the magnitude);
//!    - the BRDF in **importance transport**: look at `TransportMode` and
//!      decide which of your two directions is the slide's `ω_o` and which
//!      `ω_i` (`Brdf::eval` takes local directions: `it.frame.to_local`);
//!    - visibility: a shadow ray from the vertex to the lens point
//!      (`Ray::spawn_to` with a zero normal at the lens, `Scene::unoccluded`);
//!    - push `Splat { raster, value }`.
//! 4. **Continue** by sampling the BRDF (`Brdf::sample` — in which
//!    `TransportMode`?), updating β as in exercise 11; Russian roulette once
//!    the path has made `rr_depth` bounces (a survival probability q of your
//!    choice; unbiased). Every path must end.
//!
//! Depth, as everywhere in the course: `max_depth` = D is the largest number
//! of segments of a whole path, lens included (`None`: no limit). The light's
//! point joined to the lens is a path of 1 segment (D = 1: lights seen
//! directly); a vertex after k bounces joined to the lens has k + 1. So the
//! light path keeps at most D vertices, the light's point included.
//!
//! Conventions: directions point away from the surface; `it.wo` points back
//! where the path came from (towards the light). Smooth-shaded meshes would
//! need Veach's adjoint correction for shading normals; the graded scenes
//! have none, leave it out. `exercises::plug::StudentLightTracer` renders with
//! your function (`lesson11 render --student -i light`).
//!
//! ---
//!
//! # На български
//!
//! Задача 14 — light tracing: пътища от светлината, свързани с камерата.
//!
//! Слайдове: „Light tracing“, „Свързването с камерата“, „Какво носи един път“.
//!
//! Light tracing е path tracing, пуснат наобратно: пътят тръгва от лампа,
//! отразява се в сцената с избор по BRDF и всеки негов връх се свързва с
//! лещата на камерата. Такова свързване прави цял път от лещата до лампата:
//! една проба от интеграла по пътищата (слайдове „Интегралът по пътищата“,
//! „Какво носи един път“), чиято Monte Carlo оценка `C` извеждате вие
//! (слайд „Свързването с камерата“). Тя пада в пиксела, в който камерата
//! вижда върха, като *splat*. Важността
//! (importance) на камерата `W_e` играе ролята, която `L_e` играе за
//! лампите. Така се намира каустиката в сцената `caustic` — path tracer би
//! трябвало да уцели точкова светлина след пречупване.
//!
//! Задача: трасирайте ЕДИН светлинен път и добавете в `splats` splat-а на
//! всеки връх, който камерата вижда. Всичко, което намерите, отива във филма
//! като splat-ове (интеграторът около вас връща 0 за пробата на пиксела);
//! филмът умножава splat-овете на пиксел по `W·H / M` (M проби на пиксел
//! общо), така че стойността на splat-а е оценката `C` на един път и нищо
//! повече.
//!
//! 1. **Начало върху лампа**: изберете лампа със `Scene::choose_light` (тя
//!    дава `P(лампа)`, `LightChoice::pmf`) и излъчете лъч от нея с
//!    `Light::sample_le` (`Emission`: точката `p` върху лампата, нормалата
//!    ѝ `n`, излъченото `le` по лъча, плътността `pdf_a` на точката на
//!    единица площ и `pdf_w` на посоката на единица пространствен ъгъл).
//!    Пропуснете околната светлина (`Light::is_environment`): тук тя няма
//!    светлинни пътища. Throughput β на пътя, когато напуска лампата, е
//!    Monte Carlo теглото му дотук: колкото носи от излъчването на лампата
//!    при всичко, избрано дотук. `L_e` е radiance: на единица проектирана
//!    площ и на единица пространствен ъгъл. Точковата светлина
//!    (`is_delta_position`) няма повърхност: нейното `n` е нула, косинусът ѝ
//!    се брои за 1, а `le` е интензитетът ѝ.
//! 2. **Лампата, видяна направо**: свържете с лещата и точката `y_0` върху
//!    лампата: път от една отсечка, чиято стойност съдържа `L_e` на лампата
//!    към лещата (`Scene::emitted_by` с `LightChoice::index` на лампата) и
//!    за който са избрани само лампата и точката върху нея. Pinhole камера
//!    не може да бъде уцелена от светлинен път, така че само така камерата
//!    вижда лампа с площ.
//! 3. **Във всяка повърхност, която пътят удари** (`Scene::intersect`), освен
//!    ако BRDF ѝ е делта (`Brdf::is_delta`: огледало, стъкло — свързването им
//!    с лещата е нула), свържете върха с лещата:
//!    - точка от лещата: `plug::sample_lens` (`LensPoint` с плътността ѝ
//!      `pdf_a` на единица площ от лещата; лещата гледа към
//!      `Camera::forward`);
//!    - къде пада: `Camera::raster_of` (от света към растера), `None` там,
//!      където камерата не вижда върха (зад лещата, извън филма);
//!    - важността `W_e`: `Camera::we` на лъча от точката на лещата към върха;
//!    - геометричният член на свързването, с косинуса във върха спрямо
//!      нормалата за засенчване `it.frame.n` (светлинният път може да стигне
//!      повърхността откъм гърба ѝ: важи абсолютната стойност);
//!    - BRDF при **пренос на importance**: вижте `TransportMode` и решете коя
//!      от двете ви посоки е `ω_o` от слайда и коя `ω_i` (`Brdf::eval` взима
//!      посоки в локалната система: `it.frame.to_local`);
//!    - видимост: лъч за сянка от върха до точката на лещата (`Ray::spawn_to`
//!      с нулева нормала при лещата, `Scene::unoccluded`);
//!    - добавете `Splat { raster, value }`.
//! 4. **Продължете** с избор по BRDF (`Brdf::sample` — в кой
//!    `TransportMode`?), като обновявате β както в задача 11; руска рулетка,
//!    щом пътят е направил `rr_depth` отражения (вероятност за оцеляване q по
//!    ваш избор; неотместено). Всеки път трябва да свърши.
//!
//! Дълбочина, както навсякъде в курса: `max_depth` = D е най-големият брой
//! отсечки на целия път, включително до лещата (`None`: без ограничение).
//! Точката върху лампата, свързана с лещата, е път от 1 отсечка (D = 1:
//! лампите, видени направо); връх след k отражения, свързан с лещата, има
//! k + 1. Така светлинният път пази най-много D върха, включително точката
//! върху лампата.
//!
//! Уговорки: посоките сочат навън от повърхността; `it.wo` сочи назад,
//! откъдето е дошъл пътят (към лампата). Гладко засенчените мрежи биха
//! изисквали поправката на Veach за нормалите за засенчване (adjoint
//! correction); оценяваните сцени нямат такива, пропуснете я.
//! `exercises::plug::StudentLightTracer` рендерира с вашата функция
//! (`lesson11 render --student -i light`).

use raytracer::film::Splat;
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

/// One light path and its connections to the lens, pushed onto `splats`.
///
/// Един светлинен път и свързванията му с лещата, добавени в `splats`.
// A `Vec`, not a slice: you push onto it (clippy cannot know before you do).
#[allow(clippy::ptr_arg)]
pub fn trace_light_path(
    scene: &Scene,
    sampler: &mut Sampler,
    max_depth: Option<u32>,
    rr_depth: u32,
    splats: &mut Vec<Splat>,
) {
    // TODO: start on a light, join every vertex to the lens (a splat), continue by BRDF sampling.
    // TODO (бг): начало върху лампа, всеки връх свързан с лещата (splat), продължение с избор по BRDF.
    todo!()
}
