//! Exercise 7 — cosine-weighted hemisphere sampling and its pdf.
//!
//! Slides: "Solving with Monte Carlo" ("Решаване чрез Monte Carlo метод").
//!
//! The Monte Carlo estimate of an integral over the hemisphere divides each
//! random direction's contribution by its density `p(ω)`. Directions drawn
//! with a density proportional to `cos θ` cancel the cosine of the
//! rendering equation (and, for Lambert, the whole BRDF but its albedo).
//!
//! Part 1: `sample_cosine_hemisphere(u)`: turn two uniform numbers
//! `u ∈ [0, 1)²` into a unit direction in the upper hemisphere (`z ≥ 0`,
//! local frame) whose density per unit solid angle is proportional to
//! `cos θ`. Any correct method is fine.
//!
//! Part 2: `cosine_hemisphere_pdf(w)`: that density for the direction `w`,
//! normalized (it integrates to 1 over the hemisphere); 0 below the horizon
//! (`w.z ≤ 0`).
//!
//! Receives: the explicit random numbers `u` (never call a random generator
//! here: the grader feeds you its own numbers). Returns: the direction / its
//! density.
//!
//! ---
//!
//! # На български
//!
//! Задача 7 — избор на посоки в полусферата с тегло косинус и неговата
//! плътност.
//!
//! Слайд: „Решаване чрез Monte Carlo метод“.
//!
//! Monte Carlo оценката на интеграл по полусферата дели приноса на всяка
//! случайна посока на нейната плътност `p(ω)`. Посоки, избрани с плътност,
//! пропорционална на `cos θ`, съкращават косинуса от транспортното уравнение (а
//! при Ламберт — и цялата BRDF освен албедото ѝ).
//!
//! Част 1: `sample_cosine_hemisphere(u)`: превърнете две равномерни числа
//! `u ∈ [0, 1)²` в единична посока в горната полусфера (`z ≥ 0`, локална
//! система), чиято плътност на единица пространствен ъгъл е пропорционална на
//! `cos θ`. Всеки верен начин е добър.
//!
//! Част 2: `cosine_hemisphere_pdf(w)`: тази плътност за посоката `w`, нормирана
//! (интегралът ѝ по полусферата е 1); 0 под хоризонта (`w.z ≤ 0`).
//!
//! Получава: изрично подадените случайни числа `u` (тук никога не викайте
//! генератор на случайни числа: проверката ви подава своите числа). Връща:
//! посоката / плътността ѝ.

use raytracer::math::{Vec2, Vec3A};

/// A direction with density proportional to `cos θ`.
///
/// Посока с плътност, пропорционална на `cos θ`.
pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3A {
    // TODO: find a shape whose uniform points map to such directions.
    // TODO (бг): намерете фигура, чиито равномерно избрани точки се превръщат в такива посоки.
    todo!()
}

/// The density of [`sample_cosine_hemisphere`] per unit solid angle.
///
/// Плътността на [`sample_cosine_hemisphere`] на единица пространствен ъгъл.
pub fn cosine_hemisphere_pdf(w: Vec3A) -> f32 {
    // TODO: proportional to cos θ, integrating to 1.
    // TODO (бг): пропорционална на cos θ, с интеграл 1.
    todo!()
}
