//! Exercise 17 — photon mapping: tracing the photons, and the radiance estimate.
//!
//! Slides: "Photon mapping" ("Photon mapping"),
//! "Density estimation" ("Оценка на плътността").
//!
//! Photon mapping (Jensen) runs in two passes. First, N light paths leave
//! the lights and every one of them leaves a photon — a packet of flux — at
//! each surface it meets that is not a mirror or glass. Then, at the point
//! x a camera ray sees, the light leaving x towards the camera is estimated
//! from the photons that landed near x: a density estimate of the flux
//! arriving per unit area, turned into radiance by the BRDF.
//!
//! Part 1: `trace_photon_path(scene, paths, rr_depth, sampler, photons)`:
//! trace ONE of the `paths` = N light paths and push its photons onto
//! `photons` (`raytracer::integrator::photon::Photon`; the caller traces all
//! N, each with its own sampler, and keeps every photon).
//! - Choose a light with `Scene::choose_light` (one random number: a
//!   `LightChoice` with `choice.light` and `choice.pmf`, the probability of
//!   the choice); an environment light (`Light::is_environment`) sends no
//!   photons: the path is empty.
//! - Emit a ray with `Light::sample_le` (two pairs of random numbers): an
//!   `Emission` with the origin's density per unit area `pdf_a`, the
//!   direction's density per unit solid angle `pdf_w`, the emitted radiance
//!   `le` along the ray and the normal `n` at the origin. A point light has
//!   no surface: its `n` is zero, `le` is its intensity and there is no
//!   cosine at the light (`Emission::is_delta_position`).
//! - The flux Φ the photon starts with: this path is one Monte Carlo
//!   estimate of the light's emitted power (in the lecture's measure:
//!   `∫∫ L_e cos θ dA dω` over the lights' surfaces and directions), and the
//!   N paths share that power out. Derive it from the densities of
//!   everything you drew.
//! - Follow the ray: at each surface the ray hits, if the BRDF is not a
//!   delta (`Brdf::is_delta`), store a `Photon`: `p` the hit point, `wi` the
//!   unit direction from the hit back to where the photon came from (the
//!   hit's `it.wo`), `power` its flux Φ, and `segments` the number of
//!   segments it travelled from the light (1: straight from the light).
//!   Mirrors and glass store nothing (the camera side follows them by ray
//!   tracing instead). Then continue by sampling the BRDF
//!   (`Brdf::sample` with `TransportMode::Importance`: the photon carries
//!   flux, not radiance) and update Φ so that it stays the flux the photon
//!   carries after the bounce. A ray that leaves the scene ends the path.
//! - No depth limit: Russian roulette once the path has made `rr_depth`
//!   bounces, with a survival probability of your choice, keeping the
//!   expected flux unchanged. Every path must end.
//!
//! Part 2: `photon_radiance(map, it, brdf, search)`: the reflected radiance
//! `L_r(x, ω_o)` at the hit `it` (`x = it.p`, `ω_o = it.wo`) with BRDF
//! `brdf`, from the photons of `map` near x (the slide's sum: each photon's
//! flux weighted by the BRDF for the direction it came from, and by a
//! kernel over a disk of radius r around x).
//! - The kernel is the renderer's, Epanechnikov's: `K(d) ∝ 1 − d²/r²` for
//!   `d < r` and 0 beyond, normalized so that its integral over the disk's
//!   area is 1 (derive its constant).
//! - `Search::Radius(r)`: every photon within r of x.
//! - `Search::Nearest { k, max_radius }`: the k nearest photons, r being
//!   the distance of the k-th nearest (which then weighs 0). Only photons
//!   within `max_radius` are candidates; if there are k or fewer, use them
//!   all, over the disk of radius `max_radius`.
//! - The photons within a radius: `PhotonMap::for_each_within` (it hands
//!   you each photon with its SQUARED distance to x). Evaluate `Brdf::eval`
//!   in the local frame of the hit (`it.frame.to_local`), both directions
//!   pointing away from x. No photon near x: black.
//!
//! Direct light is NOT estimated from the photons: the integrator that wraps
//! your functions (`exercises::plug::StudentPhotonMapping`, which
//! `lesson11 render --student -i photon` renders) follows the camera ray
//! through mirrors and glass to x, adds the emission seen on the way and a
//! light sample at x (next event estimation), and reads your estimate from
//! a map of the photons with 2 or more segments (caustics through glass and
//! indirect light), as the renderer's `PhotonMapping` does.
//!
//! Returns: part 1 nothing (the photons are pushed); part 2 the estimate of
//! `L_r(x, ω_o)` (RGB).
//!
//! ---
//!
//! # На български
//!
//! Задача 17 — photon mapping: трасирането на фотоните и оценката на
//! radiance от тях.
//!
//! Слайдове: „Photon mapping“, „Оценка на плътността“.
//!
//! Photon mapping (Jensen) минава на два прохода. Първо N светлинни пътя
//! тръгват от лампите и всеки от тях оставя фотон — порция поток — във
//! всяка повърхност, която срещне и която не е огледало или стъкло. После, в
//! точката x, която вижда лъч от камерата, светлината, излизаща от x към
//! камерата, се оценява от фотоните, паднали близо до x: оценка на
//! плътността на пристигащия поток на единица площ, превърната в radiance
//! чрез BRDF.
//!
//! Част 1: `trace_photon_path(scene, paths, rr_depth, sampler, photons)`:
//! трасирайте ЕДИН от `paths` = N светлинни пътя и добавете фотоните му в
//! `photons` (`raytracer::integrator::photon::Photon`; извикващият трасира
//! всичките N, всеки със собствен sampler, и пази всеки фотон).
//! - Изберете лампа със `Scene::choose_light` (едно случайно число:
//!   `LightChoice` с `choice.light` и `choice.pmf`, вероятността на избора);
//!   околната светлина (`Light::is_environment`) не изпраща фотони: пътят е
//!   празен.
//! - Излъчете лъч с `Light::sample_le` (две двойки случайни числа):
//!   `Emission` с плътността на началото на единица площ `pdf_a`, плътността
//!   на посоката на единица пространствен ъгъл `pdf_w`, излъчената radiance
//!   `le` по лъча и нормалата `n` в началото. Точковата светлина няма
//!   повърхност: нейното `n` е нула, `le` е интензитетът ѝ и при лампата няма
//!   косинус (`Emission::is_delta_position`).
//! - Потокът Φ, с който тръгва фотонът: този път е една Monte Carlo оценка на
//!   излъчената мощност на лампата (в мярката от лекцията:
//!   `∫∫ L_e cos θ dA dω` по повърхностите и посоките на лампите), а N-те
//!   пътя си поделят тази мощност. Изведете го от плътностите на всичко, което
//!   сте избрали.
//! - Следвайте лъча: във всяка повърхност, която лъчът удари, ако BRDF не е
//!   делта (`Brdf::is_delta`), запазете `Photon`: `p` — точката на
//!   пресичането, `wi` — единичната посока от пресичането назад натам,
//!   откъдето е дошъл фотонът (`it.wo` на пресичането), `power` — потокът му
//!   Φ, и `segments` — броят отсечки, които е изминал от лампата (1: направо
//!   от лампата). Огледалата и стъклото не пазят нищо (откъм камерата те се
//!   следват с трасиране на лъчи). После продължете с избор по BRDF
//!   (`Brdf::sample` с `TransportMode::Importance`: фотонът носи поток, не
//!   radiance) и обновете Φ така, че да остане потокът, който фотонът носи
//!   след отражението. Лъч, който напусне сцената, завършва пътя.
//! - Без ограничение на дълбочината: руска рулетка, щом пътят е направил
//!   `rr_depth` отражения, с вероятност за оцеляване по ваш избор, като
//!   очакваният поток остава същият. Всеки път трябва да свърши.
//!
//! Част 2: `photon_radiance(map, it, brdf, search)`: отразената radiance
//! `L_r(x, ω_o)` в пресичането `it` (`x = it.p`, `ω_o = it.wo`) с BRDF
//! `brdf`, от фотоните на `map` близо до x (сумата от слайда: потокът на
//! всеки фотон, претеглен с BRDF за посоката, от която е дошъл, и с ядро
//! върху диск с радиус r около x).
//! - Ядрото е това на рендерера, на Епанечников: `K(d) ∝ 1 − d²/r²` за
//!   `d < r` и 0 извън него, нормирано така, че интегралът му по площта на
//!   диска да е 1 (изведете константата му).
//! - `Search::Radius(r)`: всеки фотон на разстояние до r от x.
//! - `Search::Nearest { k, max_radius }`: k-те най-близки фотона, като r е
//!   разстоянието до k-тия най-близък (който тогава тежи 0). Кандидати са
//!   само фотоните в `max_radius`; ако са k или по-малко, използвайте ги
//!   всичките, върху диска с радиус `max_radius`.
//! - Фотоните в даден радиус: `PhotonMap::for_each_within` (дава ви всеки
//!   фотон с КВАДРАТА на разстоянието му до x). Пресметнете `Brdf::eval` в
//!   локалната система на пресичането (`it.frame.to_local`), като и двете
//!   посоки сочат навън от x. Няма фотон близо до x: черно.
//!
//! Директната светлина НЕ се оценява от фотоните: интеграторът, който обвива
//! вашите функции (`exercises::plug::StudentPhotonMapping`, който рендерира
//! `lesson11 render --student -i photon`), следва лъча от камерата през
//! огледала и стъкло до x, добавя излъчването, видяно по пътя, и проба от
//! лампите в x (next event estimation), а вашата оценка чете от карта на
//! фотоните с 2 или повече отсечки (каустики през стъкло и индиректна
//! светлина), както прави `PhotonMapping` на рендерера.
//!
//! Връща: част 1 — нищо (фотоните се добавят); част 2 — оценката на
//! `L_r(x, ω_o)` (RGB).

use raytracer::brdf::Brdf;
use raytracer::integrator::photon::Photon;
use raytracer::integrator::photon_map::{PhotonMap, Search};
use raytracer::math::Color;
use raytracer::sampling::Sampler;
use raytracer::scene::{Interaction, Scene};

/// Traces light path number `i` of `paths` (its sampler given) and pushes
/// the photons it leaves onto `photons`.
///
/// Трасира светлинния път с номер `i` от `paths` (със своя sampler) и
/// добавя фотоните, които оставя, в `photons`.
#[allow(clippy::ptr_arg)] // a Vec: the photons are pushed onto it
pub fn trace_photon_path(
    scene: &Scene,
    paths: u64,
    rr_depth: u32,
    sampler: &mut Sampler,
    photons: &mut Vec<Photon>,
) {
    // TODO: choose a light, emit, follow the photon; store, bounce, roulette.
    // TODO (бг): изберете лампа, излъчете, следвайте фотона; запазване, отражение, рулетка.
    todo!()
}

/// The reflected radiance at `it` estimated from the photons of `map`.
///
/// Отразената radiance в `it`, оценена от фотоните на `map`.
pub fn photon_radiance(map: &PhotonMap, it: &Interaction, brdf: &Brdf, search: Search) -> Color {
    // TODO: the photons of the disk, its radius, the kernel, the BRDF.
    // TODO (бг): фотоните в диска, радиусът му, ядрото, BRDF.
    todo!()
}
