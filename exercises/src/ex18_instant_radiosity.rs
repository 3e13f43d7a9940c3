//! Exercise 18 — instant radiosity (Keller): virtual point lights from light
//! paths, and their light gathered at a camera hit.
//!
//! Slides: "Instant radiosity" ("Instant radiosity"),
//! "Clamping: smooth, but wrong" ("Ограничаване (clamping): гладко, но грешно"),
//! "What a path brings" ("Какво носи един път").
//!
//! Instant radiosity traces N light paths once and turns their vertices into
//! virtual point lights (VPLs); a point x the camera sees is then lit by every
//! VPL over one connection, with a shadow ray each. Joined at x, a light path
//! becomes a whole path from the camera to the light, one sample of the
//! integral over paths (slides "The integral over paths", "What a path
//! brings"): the light a VPL sends to x is that path's Monte Carlo estimate,
//! given the light path — you derive it as you derived the splat of exercise
//! 14, with x in the place of the lens. Averaged over the choice of the light
//! paths this is the rendering equation's answer: no bias, unless the
//! geometry term G of the connection is clamped. Conventions as in exercises
//! 10–14: directions point away from the surface point, D counts the
//! segments of a path.
//!
//! # Step 1: `generate_vpls`
//!
//! Trace `paths` (N) light paths with the numbers of `sampler` and return
//! their VPLs (`Vpl`, in `exercises::plug`):
//! - a path starts on a light: choose one (`Scene::choose_light`, with its
//!   probability `LightChoice::pmf`) and emit a ray from it
//!   (`Light::sample_le`: an `Emission` with its point, normal, `L_e`, the
//!   density of the point per unit area and of the direction per unit solid
//!   angle). Its first vertex `y_0` is already a VPL, `Vpl::Light`: it
//!   sends the light's own `L_e(y_0, ω)`; its `weight` is the throughput of
//!   the path at `y_0`, shared out among the N paths. Without it there is no
//!   direct light at all;
//! - every later vertex `y_k` (`k ≥ 1`) on a surface whose BRDF is not a
//!   delta (`Brdf::is_delta`: a mirror or glass can light nothing over a
//!   connection) becomes a `Vpl::Surface` whose `power` Φ is the flux the
//!   path carries there: its throughput so far (emission, then a factor per
//!   bounce), again shared by the N paths. A delta surface keeps no VPL but
//!   the path goes on through it;
//! - the path continues by sampling the BRDF (`Brdf::sample` in
//!   `TransportMode::Importance`: light flows along a light path) and plays
//!   Russian roulette once it has made `rr_depth` bounces (a survival
//!   probability of your choice; the flux must stay unbiased);
//! - depth: the gather happens at the camera's first hit, so a VPL of k
//!   segments makes a path of k + 2 segments; keep only those within
//!   `max_depth` (`Some(D)`; `None`: no limit). `D < 2`: no VPL at all.
//!
//! Lights are area lights (quads, spheres; two-sided ones emit on both
//! sides, and `Scene::emitted_by` says how much in each direction).
//!
//! # Step 2: `gather`
//!
//! The light all `vpls` send to the camera's hit `x` and that `x` reflects
//! towards `x.wo` (radiance, RGB), one connection per VPL, each with a shadow
//! ray. What you need:
//! - the BRDF at `x` (`Scene::brdf`, `Brdf::eval` in the local frame of
//!   `x.frame`), and at a `Vpl::Surface` its own BRDF, whose incoming
//!   direction is `it.wo`;
//! - what a `Vpl::Light` emits towards `x`: `Scene::emitted_by`; its
//!   `weight` and a surface VPL's `power` are what Step 1 stored;
//! - the geometry term of the connection; the normals may face either way;
//! - visibility: `Scene::unoccluded`, with `Ray::spawn_to` from `x` to the
//!   VPL's point with both geometric normals;
//! - `clamp`: `Some(g_max)` bounds the geometry term at `g_max` (the
//!   lecture's clamping: no splotches where x nears a VPL, and too dark
//!   where surfaces meet); `None`: not clamped at all. A VPL at `x` itself
//!   (zero distance) adds nothing.
//!
//! `exercises::plug::StudentVpl` puts the two together: at the first camera
//! hit, its emission plus `gather` over the VPLs of `generate_vpls`
//! (`lesson11 render --student -i vpl`, beside the renderer's `vpl`).
//!
//! ---
//!
//! # На български
//!
//! Задача 18 — instant radiosity (Keller): виртуални точкови светлини (VPL)
//! от светлинни пътища и тяхната светлина, събрана в пресичането на лъч от
//! камерата.
//!
//! Слайдове: „Instant radiosity“, „Ограничаване (clamping): гладко, но
//! грешно“, „Какво носи един път“.
//!
//! Instant radiosity трасира N светлинни пътя веднъж и превръща върховете им
//! във виртуални точкови светлини (VPL); точка x, която камерата вижда, после
//! се осветява от всяка VPL чрез едно свързване, всяко с лъч за сянка.
//! Свързан в x, светлинният път става цял път от камерата до лампата, една
//! проба от интеграла по пътищата (слайдове „Интегралът по пътищата“, „Какво
//! носи един път“): светлината, която една VPL изпраща към x, е Monte Carlo
//! оценката на този път при дадения светлинен път — изведете я така, както
//! изведохте splat-а в задача 14, с x на мястото на лещата. Осреднено по
//! избора на светлинните пътища, това е решението на транспортното уравнение:
//! без отместване, освен ако геометричният член G на свързването не е
//! ограничен. Уговорките са като в задачи 10–14: посоките сочат навън от
//! точката на повърхността, D брои отсечките на пътя.
//!
//! ## Стъпка 1: `generate_vpls`
//!
//! Трасирайте `paths` (N) светлинни пътя с числата на `sampler` и върнете
//! техните VPL (`Vpl`, в `exercises::plug`):
//! - пътят тръгва от лампа: изберете една (`Scene::choose_light`, с
//!   вероятността ѝ `LightChoice::pmf`) и излъчете лъч от нея
//!   (`Light::sample_le`: `Emission` с точката, нормалата, `L_e`, плътността
//!   на точката на единица площ и на посоката на единица пространствен
//!   ъгъл). Първият му връх `y_0` вече е VPL, `Vpl::Light`: тя изпраща
//!   собственото `L_e(y_0, ω)` на лампата; нейното `weight` е throughput на
//!   пътя в `y_0`, поделен между N-те пътя. Без нея няма никаква директна
//!   светлина;
//! - всеки следващ връх `y_k` (`k ≥ 1`) върху повърхност, чиято BRDF не е
//!   делта (`Brdf::is_delta`: огледало или стъкло не може да освети нищо
//!   чрез свързване), става `Vpl::Surface`, чието `power` Φ е потокът, който
//!   пътят носи там: throughput дотук (излъчването, после по множител на
//!   отражение), отново поделен между N-те пътя. Делта повърхност не пази
//!   VPL, но пътят продължава през нея;
//! - пътят продължава с избор по BRDF (`Brdf::sample` в
//!   `TransportMode::Importance`: светлината тече по светлинния път) и играе
//!   руска рулетка, щом е направил `rr_depth` отражения (вероятност за
//!   оцеляване по ваш избор; потокът трябва да остане неотместен);
//! - дълбочина: събирането става в първото пресичане на лъча от камерата,
//!   така че VPL след k отсечки прави път от k + 2 отсечки; пазете само тези
//!   в рамките на `max_depth` (`Some(D)`; `None`: без ограничение). `D < 2`:
//!   никаква VPL.
//!
//! Лампите са с площ (четириъгълници, сфери; двустранните светят от двете
//! страни, а `Scene::emitted_by` казва колко във всяка посока).
//!
//! ## Стъпка 2: `gather`
//!
//! Светлината, която всички `vpls` изпращат към пресичането `x` на лъча от
//! камерата и която `x` отразява към `x.wo` (radiance, RGB), по едно
//! свързване на VPL, всяко с лъч за сянка. Какво ви трябва:
//! - BRDF в `x` (`Scene::brdf`, `Brdf::eval` в локалната система на
//!   `x.frame`), а във `Vpl::Surface` — нейната собствена BRDF, чиято
//!   входяща посока е `it.wo`;
//! - какво излъчва `Vpl::Light` към `x`: `Scene::emitted_by`; нейното
//!   `weight` и `power` на VPL върху повърхност са това, което е записала
//!   Стъпка 1;
//! - геометричният член на свързването; нормалите може да сочат на която и
//!   да е страна;
//! - видимост: `Scene::unoccluded`, с `Ray::spawn_to` от `x` до точката на
//!   VPL с двете геометрични нормали;
//! - `clamp`: `Some(g_max)` ограничава геометричния член до `g_max`
//!   (ограничаването (clamping) от лекцията: без петна там, където x е близо
//!   до VPL, и твърде тъмно там, където повърхностите се срещат); `None`:
//!   никакво ограничаване. VPL в самото `x` (нулево разстояние) не добавя
//!   нищо.
//!
//! `exercises::plug::StudentVpl` събира двете: в първото пресичане на лъча
//! от камерата — излъчването там плюс `gather` по VPL от `generate_vpls`
//! (`lesson11 render --student -i vpl`, до `vpl` на рендерера).

use raytracer::math::Color;
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

use crate::plug::Vpl;

/// The VPLs of `paths` light paths: one on the light where each path starts,
/// one at every later vertex on a surface that is not a mirror or glass.
///
/// VPL на `paths` светлинни пътя: по една върху лампата, от която тръгва
/// всеки път, и по една във всеки следващ връх върху повърхност, която не е
/// огледало или стъкло.
pub fn generate_vpls(
    scene: &Scene,
    paths: u32,
    max_depth: Option<u32>,
    rr_depth: u32,
    sampler: &mut Sampler,
) -> Vec<Vpl> {
    // TODO: N light paths: a VPL on the light, one per non-delta hit, BRDF sampling, roulette.
    // TODO (бг): N светлинни пътя: VPL върху лампата, по една във всяко не-делта пресичане, избор по BRDF, рулетка.
    todo!()
}

/// The light of every VPL reflected at `x` towards `x.wo`, G clamped at
/// `clamp` (`None`: not clamped).
///
/// Светлината на всяка VPL, отразена в `x` към `x.wo`, с G, ограничено до
/// `clamp` (`None`: без ограничаване).
pub fn gather(scene: &Scene, x: &Interaction, vpls: &[Vpl], clamp: Option<f32>) -> Color {
    // TODO: for each VPL: the BRDF at x, what the VPL sends towards x, G, a shadow ray.
    // TODO (бг): за всяка VPL: BRDF в x, това, което VPL изпраща към x, G, лъч за сянка.
    todo!()
}
