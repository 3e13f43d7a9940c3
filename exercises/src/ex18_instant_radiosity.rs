//! Exercise 18 — instant radiosity (Keller): virtual point lights from light
//! paths, and their light gathered at a camera hit.
//!
//! Slides: "Instant radiosity" ("Instant radiosity"),
//! "Clamping: smooth, but wrong" ("Ограничаване (clamping): гладко, но грешно").
//!
//! Instant radiosity traces N light paths once and turns their vertices into
//! virtual point lights (VPLs); a point the camera sees is then lit by every
//! VPL over one connection, with a shadow ray each:
//!
//! ```text
//!   L(x, ω_o) = Σ_y f_r(x; ω_xy, ω_o) · G(x, y) · f_y(ω_yx) · Φ_y · V(x, y)
//! ```
//!
//! with `G(x, y)` the geometry term of the connection (exercise 15: a cosine
//! at each end, the squared distance). Averaged over the choice of the light
//! paths this is the rendering equation's answer: no bias, unless G is
//! clamped. Conventions as in exercises 10–14: directions point away from
//! the surface point, D counts the segments of a path.
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
//! towards `x.wo` (the sum above, RGB):
//! - at `x`: the BRDF (`Scene::brdf`, `Brdf::eval` in the local frame of
//!   `x.frame`) from the direction towards the VPL to `x.wo`;
//! - at the VPL: what it sends back towards `x` — for `Vpl::Light` the
//!   light's emission in that direction times its `weight`; for
//!   `Vpl::Surface` its BRDF from its incoming direction (`it.wo`) to the
//!   direction towards `x`, times its `power`;
//! - the geometry term with both cosines, each taken where it belongs, and
//!   normals that may face either way;
//! - visibility: one shadow ray (`Scene::unoccluded`, with
//!   `Ray::spawn_to` from `x` to the VPL's point with both geometric
//!   normals);
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
//! грешно“.
//!
//! Instant radiosity трасира N светлинни пътя веднъж и превръща върховете им
//! във виртуални точкови светлини (VPL); точка, която камерата вижда, после
//! се осветява от всяка VPL чрез едно свързване, всяко с лъч за сянка (сумата
//! по-горе). `G(x, y)` е геометричният член на свързването (задача 15: по
//! косинус във всеки край, разстоянието на квадрат). Осреднено по избора на
//! светлинните пътища, това е решението на транспортното уравнение: без
//! отместване, освен ако G не е ограничено. Уговорките са като в задачи
//! 10–14: посоките сочат навън от точката на повърхността, D брои отсечките
//! на пътя.
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
//! камерата и която `x` отразява към `x.wo` (сумата по-горе, RGB):
//! - в `x`: BRDF (`Scene::brdf`, `Brdf::eval` в локалната система на
//!   `x.frame`) от посоката към VPL към `x.wo`;
//! - във VPL: това, което тя изпраща обратно към `x` — за `Vpl::Light`
//!   излъчването на лампата в тази посока, умножено по нейното `weight`; за
//!   `Vpl::Surface` нейната BRDF от входящата ѝ посока (`it.wo`) към посоката
//!   към `x`, умножена по нейното `power`;
//! - геометричният член с двата косинуса, всеки взет там, където му е
//!   мястото, и нормали, които може да сочат на която и да е страна;
//! - видимост: един лъч за сянка (`Scene::unoccluded`, с `Ray::spawn_to` от
//!   `x` до точката на VPL с двете геометрични нормали);
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
