//! Unit tests of `integrator/irradiance_cache.rs`.

use raytracer::integrator::dimensions::IC_STRATUM;
use raytracer::integrator::irradiance_cache::*;
use raytracer::math::{Color, PI, Vec3A};
use raytracer::sampling::Sampler;

/// A record at the origin (normal `z`) under a ceiling at height `h`
/// whose half `y > −s` shines with radiance `L₀` (per channel `c`) and
/// whose other half is black: the receiver is `s` past the edge, on the
/// bright side if `s > 0`. With `ρ = √(s² + h²)`, integrating
/// `cos θ cos θ' / d²` over the bright half-plane gives
///
/// ```text
///   E = (π L₀/2) (1 + s/ρ),   ∂E/∂y = (π L₀/2) h²/ρ³,   ∂E/∂x = 0,
/// ```
///
/// and `∇_r E = z × F` with `F = ∫ L ω dω = (0, (π L₀/2) h/ρ, E)`:
/// `∇_r E = (−(π L₀/2) h/ρ, 0, 0)`.
fn half_plane(s: f32, h: f32, l0: Color, strata: Strata, seed: u64) -> (Color, Gradients) {
    let mut sampler = Sampler::new(seed, 0, 0);
    let (e, _, g) = strata.estimate(0.0, |j, k| {
        let w = strata.direction(j, k, IC_STRATUM.draw(&mut sampler));
        let t = h / w.z;
        let bright = w.y * t > -s;
        (if bright { l0 } else { Color::ZERO }, t)
    });
    (e, g)
}

/// Ward & Heckbert's estimators against the half-plane's closed form,
/// at 36 × 113 = 4068 rays, for a receiver half a height onto the
/// bright side, above the edge, and a height into the dark side (where
/// `E` and `∇_t E` have the sizes of a corner's), each at 16 seeds, on
/// three channels of different `L₀`. Every estimate must be within
/// 3% of the channel's largest closed-form value (`E` of the bright
/// side `π L₀`, `∂E/∂y` at the edge `π L₀ / 2h`, `|∇_r E|` at the edge
/// `π L₀/2`), and the components that vanish must stay below 3% of it.
/// Measured over 2000 seeds per position (`measure_half_plane_errors`):
/// bias below 0.01% for `E`, 0.1% for `∇_r E` and 0.7% for `∇_t E` (the
/// estimator is first order in the cells' size), standard deviations
/// below 0.1%, 0.17% and 0.2%, worst errors 0.4%, 0.65% and 1.3%. The
/// errors are sums over the thousands of cells the edge crosses, nearly
/// normal, so 3% is more than 11 standard deviations beyond the bias: a
/// false failure with other seeds has probability far below 1e-20. Ward &
/// Heckbert's `tan θ_j` at the cells' centres fails it (`∇_r E` 7% low).
#[test]
fn gradients_match_the_half_plane_closed_form() {
    let strata = Strata::for_rays(4096);
    assert_eq!((strata.m, strata.n), (36, 113));
    let h = 1.0f32;
    let l0 = Color::new(1.0, 0.5, 0.25);
    let mut worst = [0.0f32; 3];
    for s in [0.5f32, 0.0, -1.0] {
        let rho = (s * s + h * h).sqrt();
        let half = PI / 2.0;
        for seed in 0..16 {
            let (e, g) = half_plane(s, h, l0, strata, seed);
            for c in 0..3 {
                let l = l0[c];
                let exact_e = half * l * (1.0 + s / rho);
                let exact_t = Vec3A::new(0.0, half * l * h * h / (rho * rho * rho), 0.0);
                let exact_r = Vec3A::new(-half * l * h / rho, 0.0, 0.0);
                let errors = [
                    (e[c] - exact_e).abs() / (PI * l),
                    (g.translation[c] - exact_t).abs().max_element() / (half * l / h),
                    (g.rotation[c] - exact_r).abs().max_element() / (half * l),
                ];
                for (w, err) in worst.iter_mut().zip(errors) {
                    *w = w.max(err);
                }
                assert!(
                    errors.iter().all(|&err| err < 0.03),
                    "s = {s}, seed {seed}, channel {c}: relative errors (E, ∇_t, ∇_r) {errors:?}; \
                     E {} vs {exact_e}, ∇_t {} vs {exact_t}, ∇_r {} vs {exact_r}",
                    e[c],
                    g.translation[c],
                    g.rotation[c]
                );
            }
        }
    }
    eprintln!("half plane: worst relative errors (E, ∇_t, ∇_r) {worst:?}");
}

/// The measurement behind the tolerance above (run with `--ignored`).
#[test]
#[ignore = "a measurement, not a test"]
fn measure_half_plane_errors() {
    let strata = Strata::for_rays(4096);
    let h = 1.0f32;
    for s in [0.5f32, 0.0, -1.0] {
        let rho = (s * s + h * h).sqrt();
        let half = PI / 2.0;
        let exact = [
            half * (1.0 + s / rho),
            half * h * h / (rho * rho * rho),
            -half * h / rho,
        ];
        let mut stats = [(0.0f64, 0.0f64, 0.0f64); 3];
        let n = 2000;
        for seed in 0..n {
            let (e, g) = half_plane(s, h, Color::ONE, strata, seed);
            let errs = [
                (e.x - exact[0]) / PI,
                (g.translation[0].y - exact[1]) / (half / h),
                (g.rotation[0].x - exact[2]) / half,
            ];
            for (st, err) in stats.iter_mut().zip(errs) {
                st.0 += err as f64;
                st.1 += (err * err) as f64;
                st.2 = st.2.max(err.abs() as f64);
            }
        }
        for (name, st) in ["E", "∇_t", "∇_r"].iter().zip(stats) {
            let mean = st.0 / n as f64;
            let sd = (st.1 / n as f64 - mean * mean).sqrt();
            eprintln!(
                "s = {s}: {name} bias {mean:.5}, sd {sd:.5}, worst {:.5}",
                st.2
            );
        }
    }
}

/// `M × N` keeps to the rays given, near `N = πM`, and from
/// [`Strata::MIN_RAYS`] on has at least 2 bands and 6 sectors.
#[test]
fn strata_fit_the_rays() {
    assert_eq!(Strata::for_rays(128), Strata { m: 6, n: 21 });
    for rays in Strata::MIN_RAYS..20_000 {
        let s = Strata::for_rays(rays);
        assert!(s.rays() <= rays && s.m >= 2 && s.n >= 6, "{rays}: {s:?}");
        assert!(s.rays() as f32 > 0.85 * rays as f32, "{rays}: {s:?}");
    }
}

/// Gradients need cells on both sides of an edge: too few rays are refused.
#[test]
fn gradients_refuse_too_few_rays() {
    let s = IrradianceCacheSettings {
        rays: 8,
        gradients: true,
        ..Default::default()
    };
    let e = s.check().unwrap_err();
    assert!(
        e.starts_with("--ic-gradients needs --ic-rays of at least 12"),
        "{e}"
    );
    assert!(IrradianceCacheSettings { rays: 8, ..s }.check().is_err());
    assert!(IrradianceCacheSettings { rays: 12, ..s }.check().is_ok());
    assert!(
        IrradianceCacheSettings {
            gradients: false,
            ..s
        }
        .check()
        .is_ok()
    );
}
