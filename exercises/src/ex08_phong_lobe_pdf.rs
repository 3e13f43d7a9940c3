//! Exercise 8 — the density of a warp: sampling the Phong lobe.
//!
//! Slides: "Solving with Monte Carlo" ("Решаване чрез Monte Carlo метод"), "BRDF examples" ("Примери за BRDF").
//!
//! A glossy lobe is best sampled by its own shape. The renderer draws
//! directions around the lobe's axis (for Phong, `reflect(ω_o)`) with the
//! warp
//!
//! ```text
//! cos α = u₁^(1/(n+1)),   φ = 2π·u₂,
//! ```
//!
//! α being the angle from the axis, φ the angle around it, and `u₁`, `u₂`
//! uniform in [0, 1). A Monte Carlo estimate divides by the density of what
//! it draws, so that density must be known exactly.
//!
//! Task: derive the density per unit solid angle `p(ω)` of the directions
//! this warp produces, and return it as a function of `n` and `cos α`.
//! Directions with `cos α ≤ 0` are never produced: their density is 0.
//!
//! Receives: the exponent `n ≥ 0` and `cos α ∈ [−1, 1]`. Returns: `p(ω)`,
//! in sr⁻¹.
//!
//! ---
//!
//! # На български
//!
//! Задача 8 — плътността на едно преобразуване: избор на посоки по лоба на
//! Phong.
//!
//! Слайдове: „Решаване чрез Monte Carlo метод“, „Примери за BRDF“.
//!
//! Посоките за glossy лоб е най-добре да се избират по собствената му форма.
//! Рендерерът избира посоки около оста на лоба (за Phong — `reflect(ω_o)`) с
//! преобразуването
//!
//! ```text
//! cos α = u₁^(1/(n+1)),   φ = 2π·u₂,
//! ```
//!
//! където α е ъгълът от оста, φ — ъгълът около нея, а `u₁`, `u₂` са равномерни
//! в [0, 1). Monte Carlo оценката дели на плътността на това, което избира,
//! така че тази плътност трябва да е известна точно.
//!
//! Задача: изведете плътността на единица пространствен ъгъл `p(ω)` на
//! посоките, които дава това преобразуване, и я върнете като функция на `n` и
//! `cos α`. Посоки с `cos α ≤ 0` никога не се получават: плътността им е 0.
//!
//! Получава: експонентата `n ≥ 0` и `cos α ∈ [−1, 1]`. Връща: `p(ω)` в sr⁻¹.

/// The density per unit solid angle of the Phong-lobe warp.
///
/// Плътността на единица пространствен ъгъл на преобразуването по лоба на
/// Phong.
pub fn phong_lobe_pdf(n: f32, cos_alpha: f32) -> f32 {
    // TODO: the distribution of cos α first, then the change to solid angle.
    // TODO (бг): първо разпределението на cos α, после преходът към пространствен ъгъл.
    todo!()
}
