//! Exercise 16 — Metropolis light transport in primary sample space: the
//! whole chain.
//!
//! Slides: "Metropolis light transport" ("Metropolis light transport"),
//! "Metropolis light transport: its noise" ("Metropolis light transport: шумът").
//!
//! A path is the image of the uniform numbers an integrator draws: a point
//! `u` of primary sample space `[0, 1)^D` (Kelemen et al. 2002). The
//! library turns a vector `u` into its path: `path(&u)` returns a
//! [`PathSample`], the path's contributions `g_j(u)` to the pixels `j` and
//! its scalar contribution `f(u)` (`PathSample::f`, the sum of their
//! luminances). You write the Markov chain over such vectors that renders
//! `I_j = ∫ g_j(u) du` for every pixel at once, as on the slide:
//!
//! 1. **The bootstrap.** Draw `settings.bootstrap` independent vectors
//!    (`settings.dimensions` fresh numbers each, from `rng`) and evaluate
//!    them. Their mean scalar contribution estimates the normalization
//!    `b = ∫ f(u) du`. The chain starts at one of these vectors, chosen in
//!    proportion to its `f`: then the chain is in equilibrium from its first
//!    step, with no start-up bias (`raytracer::sampling::Distribution1D`
//!    picks an index in proportion to weights). If no path found light,
//!    `b̂ = 0`: leave the image black.
//! 2. **`settings.mutations` steps**, `N`. Each proposes `y` from the
//!    current `x`: with probability `settings.large_step_probability` a
//!    large step (fresh uniform numbers), else a small step (every number
//!    of `x` moved by a small random offset of size about
//!    `settings.mutation_size`, symmetric, and wrapped around so that it
//!    stays in `[0, 1)`: primary sample space is a torus here). Evaluate `y`
//!    and accept it with the probability you derive from the slide's
//!    detailed balance: the largest acceptance with which a chain that
//!    visits vectors in proportion to `f` keeps doing so.
//! 3. **The splats of both states.** The slide's identity
//!    `I_j = b · E_{f/b}[g_j / f]` says what a state visited in proportion
//!    to `f` is worth, and the `N` steps share it. Every step adds to the
//!    image, instead of the state the chain moves to, that state's expected
//!    value over the accept coin: derive each state's weight from these two
//!    facts (the factor `W·H` of the pixels is the renderer's, not yours).
//!    Splat a state with [`ChainImage::splat`]`(&state, weight)`.
//! 4. **The move**: keep `y` with its acceptance probability, else stay at
//!    `x`.
//!
//! Receives: `path`, the library's map from a vector of numbers (length
//! `settings.dimensions`, every number in `[0, 1)`) to its path; `settings`;
//! `rng`, the chain's own random numbers (`rng.next_1d()`, each uniform in
//! `[0, 1)`); `image`, all black. Returns nothing: the chain's estimate is
//! in `image`. Edge cases: paths with `f = 0` (a proposal that finds no
//! light) bring nothing and must not make a NaN.
//!
//! `exercises::plug::run_chains` runs many independent chains of yours
//! over bidirectional path tracing (`lesson11 render --integrator mlt
//! --student`), beside the renderer's own Metropolis.
//!
//! ---
//!
//! # На български
//!
//! Задача 16 — Metropolis light transport в пространството на първичните проби:
//! цялата верига.
//!
//! Слайдове: „Metropolis light transport“, „Metropolis light transport: шумът“.
//!
//! Един път е образ на равномерните числа, които интеграторът тегли: точка `u`
//! от пространството на първичните проби `[0, 1)^D` (Kelemen и съавтори, 2002).
//! Библиотеката превръща вектор `u` в неговия път: `path(&u)` връща
//! [`PathSample`] — приносите на пътя `g_j(u)` към пикселите `j` и скаларния му
//! принос `f(u)` (`PathSample::f`, сборът от яркостите им). Вие пишете
//! марковската верига над такива вектори, която рендерира `I_j = ∫ g_j(u) du`
//! за всички пиксели наведнъж, както на слайда:
//!
//! 1. **Bootstrap.** Изтеглете `settings.bootstrap` независими вектора (всеки
//!    от `settings.dimensions` нови числа от `rng`) и ги пресметнете. Средният
//!    им скаларен принос оценява нормировката `b = ∫ f(u) du`. Веригата започва
//!    от един от тези вектори, избран пропорционално на неговото `f`: тогава тя
//!    е в равновесие от първата си стъпка, без отместване от началото
//!    (`raytracer::sampling::Distribution1D` избира индекс пропорционално на
//!    тегла). Ако никой път не е намерил светлина, `b̂ = 0`: оставете картината
//!    черна.
//! 2. **`settings.mutations` стъпки**, `N`. Всяка предлага `y` от текущото `x`:
//!    с вероятност `settings.large_step_probability` — голяма стъпка (нови
//!    равномерни числа), иначе — малка стъпка (всяко число на `x` се отмества с
//!    малко случайно отместване с размер около `settings.mutation_size`,
//!    симетрично, и се увива така, че да остане в `[0, 1)`: тук пространството
//!    на първичните проби е тор). Пресметнете `y` и го приемете с вероятността,
//!    която изведете от детайлния баланс от слайда: най-голямото приемане, при
//!    което верига, посещаваща векторите пропорционално на `f`, продължава да
//!    го прави.
//! 3. **Splat-овете на двете състояния.** Тъждеството от слайда
//!    `I_j = b · E_{f/b}[g_j / f]` казва колко струва състояние, посещавано
//!    пропорционално на `f`, а `N`-те стъпки си го поделят. Всяка стъпка добавя
//!    към картината вместо състоянието, в което преминава веригата, очакваната
//!    стойност на това състояние по монетата на приемането: изведете теглото на
//!    всяко състояние от тези два факта (множителят `W·H` на пикселите е на
//!    рендерера, не ваш). Добавете състояние с
//!    [`ChainImage::splat`]`(&state, weight)`.
//! 4. **Преходът**: задръжте `y` с вероятността му за приемане, иначе останете
//!    в `x`.
//!
//! Получава: `path`, функцията на библиотеката, която превръща вектор от числа
//! (с дължина `settings.dimensions`, всяко число в `[0, 1)`) в неговия път;
//! `settings`; `rng`, собствените случайни числа на веригата (`rng.next_1d()`,
//! всяко равномерно в `[0, 1)`); `image`, изцяло черна. Не връща нищо: оценката
//! на веригата е в `image`. Гранични случаи: пътища с `f = 0` (предложение,
//! което не намира светлина) не носят нищо и не бива да дават NaN.
//!
//! `exercises::plug::run_chains` пуска много ваши независими вериги над
//! bidirectional path tracing (`lesson11 render --integrator mlt --student`),
//! до собствения Metropolis на рендерера.

use raytracer::render::metropolis::chain::PathSample;
use raytracer::sampling::Sampler;

use crate::plug::{ChainImage, ChainSettings};

/// One Metropolis chain: the bootstrap, then `settings.mutations` steps,
/// splatted into `image`.
///
/// Една верига на Metropolis: bootstrap, после `settings.mutations` стъпки,
/// добавени в `image`.
pub fn metropolis_chain(
    path: &dyn Fn(&[f32]) -> PathSample,
    settings: &ChainSettings,
    rng: &mut Sampler,
    image: &mut ChainImage,
) {
    // TODO: the bootstrap (b̂ and the start), then the steps: propose, accept, splat both, move.
    // TODO (бг): bootstrap (b̂ и началото), после стъпките: предложение, приемане, splat на двете,
    // преход.
    todo!()
}
