//! Exercise 1 — the two eyes of a stereo camera, converged on the screen.
//!
//! Slides: "Stereoscopic rendering" ("Стереоскопично рендериране"),
//! "Result" ("Резултат"), "stereoSeparation" ("stereoSeparation").
//!
//! The lecture renders two frames from two viewpoints moved apart along the
//! camera's `rightDir`; the distance between the two virtual cameras is
//! `stereoSeparation`. Here both eyes keep the middle camera's view
//! direction (a parallel rig: no eye is turned towards anything), so their
//! image planes stay parallel and a point lands at the same height in both
//! frames. Left alone, two parallel eyes see a point at the same place in
//! both frames only if it is infinitely far away: everything in the scene
//! would float in front of the screen. The screen should lie at the
//! convergence distance `C` (measured along the view direction) instead.
//!
//! Each eye therefore slides its image window sideways, within its own
//! image plane, by `CameraParams::shift` (an off-axis, asymmetric frustum).
//! The shift is measured on the image plane at distance 1 in front of the
//! eye, in the units of that plane (as `raytracer::camera` documents its
//! image window), `x` along `rightDir`. Derive how far, and which way, each
//! window must slide so that every point on the plane at depth `C` lands on
//! the same pixel in both eyes' frames, and on the pixel where the middle
//! camera sees it.
//!
//! Task: from the (middle) camera, `stereo_separation` `s` and the
//! convergence distance `C > 0`, return the parameters of the left and the
//! right eye's cameras:
//! - the middle camera sits halfway between the eyes, the left eye on the
//!   side of −rightDir;
//! - both eyes look in the middle camera's direction, with its `up`;
//! - each eye's window shift is the middle camera's own `shift` (its window
//!   may already be off-centre) plus the eye's sideways slide; nothing
//!   moves up or down;
//! - the lens and the field of view stay as they are.
//!
//! Receives: the camera (`Camera::params`, `Camera::position`,
//! `Camera::right_dir`, `Camera::forward`), `s` in metres, `C` in metres.
//! Returns: `(left, right)` camera parameters.
//!
//! The renderer builds a stereo pair with it
//! (`exercises::plug::stereo_cameras`).
//!
//! ---
//!
//! # На български
//!
//! Задача 1 — двете очи на стерео камера, събрани върху екрана.
//!
//! Слайдове: „Стереоскопично рендериране“, „Резултат“, „stereoSeparation“.
//!
//! Лекцията рендерира два кадъра от две гледни точки, раздалечени по посоката
//! `rightDir` на камерата; разстоянието между двете виртуални камери е
//! `stereoSeparation`. Тук и двете очи запазват посоката на гледане на средната
//! камера (успоредна двойка: никое око не е обърнато към нищо), така че
//! равнините на образа им остават успоредни и една точка попада на една и съща
//! височина в двата кадъра. Оставени така, две успоредни очи виждат точка на
//! едно и също място в двата кадъра само ако тя е безкрайно далеч: всичко в
//! сцената би изплувало пред екрана. Екранът трябва вместо това да е на
//! разстоянието на конвергенция `C` (мерено по посоката на гледане).
//!
//! Затова всяко око плъзга прозореца на образа си встрани, в собствената си
//! равнина на образа, с `CameraParams::shift` (изместена, несиметрична пирамида
//! на видимост — off-axis). Плъзгането се мери в равнината на образа на
//! разстояние 1 пред окото, в единиците на тази равнина (както
//! `raytracer::camera` описва прозореца на образа си), с `x` по `rightDir`.
//! Изведете колко и накъде трябва да се плъзне всеки прозорец, така че всяка
//! точка от равнината на дълбочина `C` да попадне в един и същи пиксел в
//! кадрите на двете очи, и то в пиксела, в който я вижда средната камера.
//!
//! Задача: по (средната) камера, `stereo_separation` `s` и разстоянието на
//! конвергенция `C > 0` върнете параметрите на камерите на лявото и на дясното
//! око:
//! - средната камера е по средата между очите, лявото око е откъм −rightDir;
//! - и двете очи гледат в посоката на средната камера, с нейното `up`;
//! - плъзгането на прозореца на всяко око е собственото `shift` на средната
//!   камера (прозорецът ѝ може вече да е изместен от центъра) плюс страничното
//!   плъзгане на окото; нищо не се мести нагоре или надолу;
//! - лещата и зрителното поле остават каквито са.
//!
//! Получава: камерата (`Camera::params`, `Camera::position`,
//! `Camera::right_dir`, `Camera::forward`), `s` в метри, `C` в метри. Връща:
//! параметрите на камерите `(left, right)`.
//!
//! Рендерерът строи стерео двойка с нея (`exercises::plug::stereo_cameras`).

use raytracer::camera::{Camera, CameraParams};

/// The camera parameters `(left, right)` of the two eyes.
///
/// Параметрите на камерите `(left, right)` на двете очи.
pub fn stereo_eyes(
    camera: &Camera,
    stereo_separation: f32,
    convergence: f32,
) -> (CameraParams, CameraParams) {
    // TODO: move each eye along rightDir, keep the view direction, and slide
    // each window so that depth `convergence` has zero parallax.
    // TODO (бг): преместете всяко око по rightDir, запазете посоката на гледане и плъзнете всеки
    // прозорец така, че дълбочината `convergence` да няма паралакс.
    todo!()
}
