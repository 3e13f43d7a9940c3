//! Exercise 15 — bidirectional path tracing: the connections and their weights.
//!
//! Slides: "Bidirectional path tracing" ("Bidirectional path tracing"),
//! "Strategies" ("Стратегии"), "Combining the strategies" ("Съчетаване на
//! стратегиите").
//!
//! The library grows, for every pixel sample, a camera subpath
//! `camera = [z_0, z_1, …]` (`z_0` on the lens) and a light subpath
//! `light = [y_0, y_1, …]` (`y_0` on a light) by random walks
//! (`raytracer::integrator::subpath`). You write what bidirectional path
//! tracing does with them: every strategy `(s, t)` — the first `s` light
//! vertices and the first `t` camera vertices joined by one edge
//! `y_{s−1} — z_{t−1}` into the path `x̄ = z_0 … z_{t−1} y_{s−1} … y_0` of
//! `s + t` vertices — gives an estimate of the light carried by such paths,
//! and multiple importance sampling weighs the estimates of all strategies
//! that could have made the same path. `exercises::plug::StudentBdpt` calls
//! your `connect` and `mis_weight` for every `(s, t)` with `t ≥ 1`,
//! `s + t ≥ 2` and `s + t ≤ D + 1` and renders with them
//! (`lesson11 render --student -i bdpt`).
//!
//! **The vertices** (`raytracer::integrator::vertex::Vertex`). Each has its
//! position `.p()`, its kind (`VertexKind::Camera`, `Light`, `Surface`), its
//! throughput `.beta` (the subpath's weight up to this vertex, everything
//! before the vertex's own scattering: the camera side's is a radiance
//! weight, the light side's a power estimate), and two densities per unit
//! AREA at this vertex: `.pdf_fwd_a`, with which its own subpath generated
//! it, and `.pdf_rev_a`, with which the other subpath would have generated
//! it (the same walk run backwards). `.pdf_rev_a` is valid for all but the
//! last two vertices of each prefix: for those it depends on the vertex
//! across the edge. `.delta` marks a vertex where the walk scattered off a
//! delta BRDF (a mirror): its sampling densities are stored as 0.
//! Toolbox on a vertex: `Vertex::f` (the BRDF from `ω_o` — the direction to
//! its predecessor in its own subpath — to a given direction; at a light
//! vertex the emitted radiance `L_e` in that direction), `Vertex::f_importance`
//! (the same for a light-subpath vertex, which carries importance),
//! `Vertex::abs_cos` (the cosine a vertex uses: shading normal on a surface,
//! the light's normal, none at a point light), `Vertex::le_towards`,
//! `Vertex::is_connectible`, `Vertex::is_delta_light`, `Vertex::pdf_a` (the
//! area density at a target vertex of sampling it from this one, having
//! arrived from a given predecessor), `Vertex::pdf_light_a` and
//! `Vertex::pdf_light_origin_a` (the densities of a light path that starts at
//! this emitter point), `vertex::visible`, `Camera::sample_wi`.
//!
//! **Part 1: `geometry_term(x, nx, y, ny)`**, `G(x ↔ y)`, defined by
//! `|cos θ_x| dω_x = G(x ↔ y) dA_y`: it turns an integral over directions at
//! x (with the cosine at x) into one over the area at y. θ_x lies between
//! `nx` and the edge at x, θ_y between `ny` and the edge at y; the normals
//! may face either way and `G ≥ 0`. Visibility is the caller's job; `x ≠ y`.
//!
//! **Part 2: `connect(scene, light, camera, s, t, sampler)`**, the
//! UNWEIGHTED contribution `C_{s,t}` of one strategy: the path's
//! measurement contribution (the lecture's `f_j(x̄)`: emission, the BRDFs,
//! the geometry terms, the camera's importance) divided by the density with
//! which the strategy made the path, both in the area measure. The
//! throughputs hold everything on each side of the edge; the edge brings
//! what depends on both ends. Cases:
//! - `s = 0`: the camera subpath reached an emitter by itself at `z_{t−1}`;
//! - `t = 1`: `y_{s−1}` is joined to a point on the lens, drawn with
//!   `Camera::sample_wi` from `sampler.next_2d()` (exercise 14's
//!   connection): the result lands at `CameraSample::raster` (return it in
//!   `raster`, and the lens point as `Vertex::camera(p_lens, Color::ZERO)` in
//!   `lens`);
//! - otherwise `y_{s−1}` and `z_{t−1}` are joined directly (`s = 1` too:
//!   `y_0`, the light point of the light subpath, is a vertex like the
//!   others, its `f` is `L_e`). Each end scatters from its own predecessor
//!   towards the other end; mind which side carries importance.
//!
//! `None` where the contribution is zero: nothing emitted, an end that cannot
//! be connected (a delta BRDF), the two ends not visible to each other, the
//! lens point not seeing `y_{s−1}`.
//!
//! **Part 3: `mis_weight(scene, light, camera, s, t, lens)`**, the weight of
//! strategy `(s, t)` by the power heuristic with exponent 2 over every
//! strategy `(s', t')`, `s' + t' = s + t`, `t' ≥ 1`, that could have made
//! the same path. Derive each strategy's density from the vertices: a
//! strategy's density is the product over the path's vertices (all but the
//! lens point `z_0`, common to all) of each vertex's area density from the
//! side that made it in that strategy — the camera side for the first `t'`
//! vertices, the light side for the rest. Use the stored `.pdf_fwd_a` /
//! `.pdf_rev_a`; but a vertex's density from the other side depends on the
//! vertex the path now comes from, so the connection changes some of them
//! next to the edge: work out which, and compute those anew for this path
//! (`Vertex::pdf_a`, `Vertex::pdf_light_a`, `Vertex::pdf_light_origin_a`).
//! `lens`, if any, takes the place of `camera[0]` (for `t = 1` without a
//! `lens`, `camera[0]` is the lens point). The slices are shared: copy what
//! you change. Count every strategy of this renderer, the shortest paths
//! too: a path of two vertices has the strategies (0, 2) and (1, 1).
//!
//! Impossible strategies have density 0 and count for nothing: one whose
//! edge would end at a vertex with a delta BRDF (mirror), or `s' = 0` ending
//! on a point light (no ray hits it). If the edge of `(s, t)` itself ends
//! at a vertex with a delta BRDF, return 0. A delta's own density is the same delta in every strategy that
//! can make the path, so it does not change the weights (it is stored as 0).
//! The weights of the possible strategies of one path sum to 1.
//!
//! Receives: the scene, both subpaths (at least `s` and `t` vertices), the
//! strategy; `connect` a sampler for `t = 1`. Returns: `C_{s,t}` (RGB) / the
//! weight in [0, 1].
//!
//! ---
//!
//! # На български
//!
//! Задача 15 — bidirectional path tracing: свързванията и техните тегла.
//!
//! Слайдове: „Bidirectional path tracing“, „Стратегии“, „Съчетаване на
//! стратегиите“.
//!
//! За всяка проба на пиксел библиотеката строи чрез случайни разходки подпът от
//! камерата `camera = [z_0, z_1, …]` (`z_0` върху лещата) и подпът от
//! светлината `light = [y_0, y_1, …]` (`y_0` върху лампа)
//! (`raytracer::integrator::subpath`). Вие пишете какво прави bidirectional
//! path tracing с тях: всяка стратегия `(s, t)` — първите `s` върха от
//! светлината и първите `t` върха от камерата, съединени с едно ребро
//! `y_{s−1} — z_{t−1}` в пътя `x̄ = z_0 … z_{t−1} y_{s−1} … y_0` от `s + t`
//! върха — дава оценка на светлината, пренесена по такива пътища, а multiple
//! importance sampling претегля оценките на всички стратегии, които биха могли
//! да направят същия път. `exercises::plug::StudentBdpt` вика вашите `connect`
//! и `mis_weight` за всяко `(s, t)` с `t ≥ 1`, `s + t ≥ 2` и `s + t ≤ D + 1` и
//! рендерира с тях (`lesson11 render --student -i bdpt`).
//!
//! **Върховете** (`raytracer::integrator::vertex::Vertex`). Всеки има положение
//! `.p()`, вид (`VertexKind::Camera`, `Light`, `Surface`), throughput `.beta`
//! (теглото на подпътя до този връх, всичко преди собственото разсейване на
//! върха: откъм камерата това е тегло на radiance, откъм светлината — оценка на
//! мощност) и две плътности на единица ПЛОЩ в този връх: `.pdf_fwd_a`, с която
//! го е създал собственият му подпът, и `.pdf_rev_a`, с която би го създал
//! другият подпът (същата разходка, пусната наобратно). `.pdf_rev_a` е валидна
//! за всички върхове без последните два на всеки префикс: за тях тя зависи от
//! върха от другата страна на реброто. `.delta` бележи връх, в който разходката
//! се е разсеяла от делта BRDF (огледало): плътностите на избора там са
//! записани като 0. Инструменти за връх: `Vertex::f` (BRDF от `ω_o` — посоката
//! към предшественика му в собствения му подпът — към дадена посока; във връх
//! върху лампа — излъчената radiance `L_e` в тази посока),
//! `Vertex::f_importance` (същото за връх от подпътя от светлината, който носи
//! importance), `Vertex::abs_cos` (косинусът, който ползва върхът: нормалата за
//! засенчване върху повърхност, нормалата на лампата, никакъв при точкова
//! светлина), `Vertex::le_towards`, `Vertex::is_connectible`,
//! `Vertex::is_delta_light`, `Vertex::pdf_a` (плътността на единица площ в
//! целеви връх, с която той се избира от този, когато сме дошли от даден
//! предшественик), `Vertex::pdf_light_a` и `Vertex::pdf_light_origin_a`
//! (плътностите на светлинен път, който тръгва от тази точка на излъчвател),
//! `vertex::visible`, `Camera::sample_wi`.
//!
//! **Част 1: `geometry_term(x, nx, y, ny)`**, `G(x ↔ y)`, определен чрез
//! `|cos θ_x| dω_x = G(x ↔ y) dA_y`: той превръща интеграл по посоките в x (с
//! косинуса в x) в интеграл по площта в y. θ_x е между `nx` и реброто в x, θ_y
//! — между `ny` и реброто в y; нормалите може да сочат на която и да е страна,
//! а `G ≥ 0`. Видимостта е грижа на извикващия; `x ≠ y`.
//!
//! **Част 2: `connect(scene, light, camera, s, t, sampler)`**, НЕПРЕТЕГЛЕНИЯТ
//! принос `C_{s,t}` на една стратегия: приносът на пътя (`f_j(x̄)` от лекцията:
//! излъчването, BRDF-ите, геометричните членове, важността на камерата),
//! разделен на плътността, с която стратегията е направила пътя, и двете в
//! мярката по площ. Throughput-ите съдържат всичко от двете страни на реброто;
//! реброто добавя това, което зависи от двата му края. Случаи:
//! - `s = 0`: подпътят от камерата сам е стигнал до излъчвател в `z_{t−1}`;
//! - `t = 1`: `y_{s−1}` се свързва с точка от лещата, избрана с
//!   `Camera::sample_wi` от `sampler.next_2d()` (свързването от задача 14):
//!   резултатът пада в `CameraSample::raster` (върнете го в `raster`, а точката
//!   от лещата като `Vertex::camera(p_lens, Color::ZERO)` в `lens`);
//! - иначе `y_{s−1}` и `z_{t−1}` се свързват направо (и при `s = 1`: `y_0`,
//!   точката от лампата на подпътя от светлината, е връх като другите, неговото
//!   `f` е `L_e`). Всеки край се разсейва от собствения си предшественик към
//!   другия край; внимавайте коя страна носи importance.
//!
//! `None` там, където приносът е нула: нищо не е излъчено, край, който не може
//! да се свърже (делта BRDF), двата края не се виждат един друг, точката от
//! лещата не вижда `y_{s−1}`.
//!
//! **Част 3: `mis_weight(scene, light, camera, s, t, lens)`**, теглото на
//! стратегията `(s, t)` по степенната евристика с показател 2 спрямо всяка
//! стратегия `(s', t')`, `s' + t' = s + t`, `t' ≥ 1`, която би могла да направи
//! същия път. Изведете плътността на всяка стратегия от върховете: плътността
//! на една стратегия е произведението по върховете на пътя (всички без точката
//! от лещата `z_0`, обща за всички) на плътността на единица площ на всеки връх
//! откъм страната, която го е направила в тази стратегия — откъм камерата за
//! първите `t'` върха, откъм светлината за останалите. Ползвайте записаните
//! `.pdf_fwd_a` / `.pdf_rev_a`; но плътността на връх откъм другата страна
//! зависи от върха, от който сега идва пътят, така че свързването променя някои
//! от тях до реброто: преценете кои и ги пресметнете наново за този път
//! (`Vertex::pdf_a`, `Vertex::pdf_light_a`, `Vertex::pdf_light_origin_a`).
//! `lens`, ако го има, заема мястото на `camera[0]` (при `t = 1` без `lens`
//! `camera[0]` е точката от лещата). Срезовете са общи: копирайте това, което
//! променяте. Бройте всяка стратегия на този рендерер, и на най-късите пътища:
//! път от два върха има стратегиите (0, 2) и (1, 1).
//!
//! Невъзможните стратегии имат плътност 0 и не се броят: такава, чието ребро би
//! завършило във връх с делта BRDF (огледало), или `s' = 0`, завършваща в
//! точкова светлина (никой лъч не я удря). Ако самото ребро на `(s, t)`
//! завършва във връх с делта BRDF, върнете 0. Плътността на самата делта е
//! същата делта във всяка стратегия, която може да направи пътя, така че тя не
//! променя теглата (записана е като 0). Теглата на възможните стратегии за един
//! път имат сбор 1.
//!
//! Получава: сцената, двата подпътя (поне `s` и `t` върха), стратегията;
//! `connect` — и sampler за `t = 1`. Връща: `C_{s,t}` (RGB) / теглото в [0, 1].

use raytracer::integrator::vertex::Vertex;
use raytracer::math::Vec3A;
use raytracer::sampling::Sampler;
use raytracer::scene::Scene;

use crate::plug::BdptConnection;

/// The geometry term `G(x ↔ y)`.
///
/// Геометричният член `G(x ↔ y)`.
pub fn geometry_term(x: Vec3A, nx: Vec3A, y: Vec3A, ny: Vec3A) -> f32 {
    // TODO: start from exercise 12's change of measure.
    // TODO (бг): започнете от смяната на мярката в задача 12.
    todo!()
}

/// The unweighted contribution of strategy `(s, t)`.
///
/// Непретегленият принос на стратегията `(s, t)`.
pub fn connect(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    sampler: &mut Sampler,
) -> Option<BdptConnection> {
    // TODO: s = 0, t = 1, and the edge between y_{s−1} and z_{t−1}.
    // TODO (бг): s = 0, t = 1 и реброто между y_{s−1} и z_{t−1}.
    todo!()
}

/// The MIS weight (power heuristic) of strategy `(s, t)`.
///
/// Теглото по MIS (степенната евристика) на стратегията `(s, t)`.
pub fn mis_weight(
    scene: &Scene,
    light: &[Vertex],
    camera: &[Vertex],
    s: usize,
    t: usize,
    lens: Option<Vertex>,
) -> f32 {
    // TODO: every strategy's density relative to this one's, from the vertices.
    // TODO (бг): плътността на всяка стратегия спрямо тази на (s, t), от върховете.
    todo!()
}
