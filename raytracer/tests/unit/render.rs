//! Unit tests of `render.rs`.

use indicatif::ProgressStyle;
use raytracer::film::Splat;
use raytracer::integrator::{Integrator, stop};
use raytracer::math::Vec2;
use raytracer::math::{Color, UVec2};
use raytracer::render::*;
use raytracer::sampling::Sampler;
use raytracer::scene::{RenderSettings, Scene};
use std::sync::atomic::AtomicU64;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

fn options(spp: u32, threads: usize, tile_size: u32) -> RenderOptions {
    RenderOptions {
        spp,
        seed: 17,
        threads: Some(threads),
        tile_size,
        progress: false,
        label: String::from("test"),
    }
}

/// A toy integrator: many random numbers, a value from them, up to three
/// splats at random positions (some off the film, some in the same
/// pixel), now and then an invalid value. The left tiles cost 50 times
/// more than the others, so that units finish out of order.
fn toy(pixel: UVec2, s: &mut Sampler, splats: &mut Vec<Splat>) -> Color {
    let mut acc = 0.0;
    for _ in 0..if pixel.x < 8 { 2000 } else { 40 } {
        acc += s.next_1d();
    }
    let n = (s.next_1d() * 4.0) as usize;
    for _ in 0..n {
        let raster = s.next_2d() * Vec2::new(25.0, 19.0) - Vec2::ONE;
        let v = s.next_1d();
        splats.push(Splat {
            raster,
            value: Color::new(v, v * v, 1.0 / (v + 1e-3)),
        });
    }
    if s.next_1d() < 0.01 {
        return Color::splat(f32::NAN);
    }
    Color::new(acc, s.next_1d(), pixel.x as f32 * s.next_1d())
}

#[test]
fn same_image_on_any_number_of_threads() {
    // 23×17 is not a multiple of the tile; 20 spp is a full and a partial pass.
    let runs: Vec<_> = [1, 2, 3]
        .iter()
        .map(|&t| render_pixels_with_stop(23, 17, &options(20, t, 8), &AtomicBool::new(false), toy))
        .collect();
    for r in &runs {
        assert!(!r.stats.interrupted);
        assert_eq!(r.stats.samples, 23 * 17 * 20);
        assert_eq!(r.stats.nonfinite, runs[0].stats.nonfinite);
        assert!(r.film == runs[0].film, "the films' sums differ");
        assert_eq!(r.film.image().bits(), runs[0].film.image().bits());
        assert_eq!(
            r.film.variance_image().bits(),
            runs[0].film.variance_image().bits()
        );
    }
    assert!(runs[0].stats.nonfinite > 0);
    // The test could not fail if the seed were ignored: another seed differs.
    let other = RenderOptions {
        seed: 18,
        ..options(20, 2, 8)
    };
    let r = render_pixels_with_stop(23, 17, &other, &AtomicBool::new(false), toy);
    assert_ne!(r.film.image().bits(), runs[0].film.image().bits());
}

/// A watcher sees the film grow; at every complete pass it is the film of
/// a render with that many samples per pixel, bit for bit (the lab's
/// progressive picture equals `lesson11 render --spp N`), and the last
/// one is the finished film.
#[test]
fn watched_passes_equal_shorter_renders() {
    let stop = AtomicBool::new(false);
    let mut complete = Vec::new();
    let mut calls = 0;
    let r = render_pixels_watched(23, 17, &options(40, 2, 8), &stop, toy, &mut |p| {
        calls += 1;
        if p.pass_complete {
            complete.push((p.complete_spp, p.film.clone()));
        }
    });
    assert_eq!(calls, 9 * 3, "one call per merged unit (9 tiles, 3 passes)");
    let spps: Vec<u32> = complete.iter().map(|c| c.0).collect();
    assert_eq!(spps, [16, 32, 40]);
    for (spp, film) in &complete {
        let alone = render_pixels_with_stop(23, 17, &options(*spp, 3, 8), &stop, toy);
        assert!(*film == alone.film, "the film at {spp} spp differs");
    }
    assert!(complete.last().unwrap().1 == r.film);
}

/// Pixel `(x, y)`, sample `k` uses `Sampler::new(seed, y·width + x, k)`.
#[test]
fn random_numbers_have_the_documented_address() {
    let (w, h, spp) = (5, 3, 7);
    let r = render_pixels_with_stop(
        w,
        h,
        &options(spp, 2, 2),
        &AtomicBool::new(false),
        |_, s, _| Color::splat(s.next_1d()),
    );
    for y in 0..h {
        for x in 0..w {
            let mean: f64 = (0..spp as u64)
                .map(|k| Sampler::new(17, (y * w + x) as u64, k).next_1d() as f64)
                .sum::<f64>()
                / spp as f64;
            assert!((r.film.image().get(x, y).x as f64 - mean).abs() < 1e-6);
        }
    }
}

/// `X = (u1, u2, u3)` uniform: every pixel mean is 1/2 and the variance
/// of the mean is (1/12)/N. 192 pixel-channels at 6 standard errors: a
/// false failure has probability < 192 · 2e-9 < 1e-6. The average
/// estimated variance has a relative standard error of about 0.4%
/// (kurtosis of the uniform), checked to 3%. The scatter of the means
/// across pixels must match the predicted variance: a chi-square with
/// 191 degrees of freedom, whose ratio lies in [0.45, 1.6] with
/// probability > 1 − 1e-6.
#[test]
fn mean_and_variance_of_a_uniform_variable() {
    let n = 256;
    let r = render_pixels_with_stop(
        8,
        8,
        &options(n, 2, 4),
        &AtomicBool::new(false),
        |_, s, _| Color::new(s.next_1d(), s.next_1d(), s.next_1d()),
    );
    let predicted = 1.0 / 12.0 / n as f64;
    let (img, var) = (r.film.image(), r.film.variance_image());
    let (mut sum_var, mut scatter) = (0.0, 0.0);
    for (m, v) in img.pixels.iter().zip(&var.pixels) {
        for c in 0..3 {
            let d = m[c] as f64 - 0.5;
            assert!(d.abs() < 6.0 * predicted.sqrt(), "mean {}", m[c]);
            sum_var += v[c] as f64;
            scatter += d * d;
        }
    }
    let avg_var = sum_var / 192.0;
    assert!(
        (avg_var / predicted - 1.0).abs() < 0.03,
        "{avg_var} vs {predicted}"
    );
    let ratio = scatter / 192.0 / predicted;
    assert!((0.45..1.6).contains(&ratio), "scatter ratio {ratio}");
}

#[test]
fn splats_are_normalized_per_sample_on_the_film() {
    // Every sample splats (1, 2, 3) into pixel (1, 2): 4·3·5 = 60 splats,
    // scaled by W·H/M = 12/60, give W·H·(1, 2, 3) = (12, 24, 36).
    let r = render_pixels_with_stop(
        4,
        3,
        &options(5, 2, 2),
        &AtomicBool::new(false),
        |_, _, splats| {
            splats.push(Splat {
                raster: Vec2::new(1.5, 2.5),
                value: Color::new(1.0, 2.0, 3.0),
            });
            Color::ZERO
        },
    );
    let img = r.film.image();
    assert_eq!(img.get(1, 2), Color::new(12.0, 24.0, 36.0));
    let others: f32 = img.pixels.iter().map(|c| c.element_sum()).sum();
    assert_eq!(others, 72.0);
    // Every path brings the same value: no variance.
    assert!(r.film.variance_image().get(1, 2).max_element() < 1e-9);
}

/// Paths splat 1 into pixel (0, 0) with probability 1/2: the pixel is
/// `(W·H/M) Σ Y` with mean W·H/2 = 8 and variance (W·H)²/(4M) = 64/M.
/// The estimated variance is within 5% of that (its relative standard
/// error is about 1/√M ≈ 1.1%: a 4.5-sigma margin, false failure < 1e-5),
/// and the estimate within 6 standard deviations of 8.
#[test]
fn splat_variance_matches_a_bernoulli_path() {
    let (w, h, spp) = (4, 4, 512);
    let r = render_pixels_with_stop(
        w,
        h,
        &options(spp, 2, 4),
        &AtomicBool::new(false),
        |_, s, splats| {
            if s.next_1d() < 0.5 {
                splats.push(Splat {
                    raster: Vec2::new(0.25, 0.75),
                    value: Color::ONE,
                });
            }
            Color::ZERO
        },
    );
    let m = (w * h * spp) as f64;
    let predicted = 64.0 / m;
    let var = r.film.variance_image().get(0, 0).x as f64;
    assert!((var / predicted - 1.0).abs() < 0.05, "{var} vs {predicted}");
    let value = r.film.image().get(0, 0).x as f64;
    assert!((value - 8.0).abs() < 6.0 * predicted.sqrt(), "{value}");
    assert_eq!(r.film.variance_image().get(1, 0), Color::ZERO);
}

#[test]
fn invalid_values_are_counted_and_kept_out() {
    let r = render_pixels_with_stop(
        6,
        5,
        &options(8, 2, 4),
        &AtomicBool::new(false),
        |p, s, splats| {
            let k = s.next_1d();
            splats.push(Splat {
                raster: p.as_vec2(),
                value: Color::new(f32::INFINITY, 0.0, 0.0),
            });
            if p.x == 2 {
                // Every value of pixel column 2 is NaN or negative.
                return if k < 0.5 {
                    Color::splat(f32::NAN)
                } else {
                    Color::splat(-1.0)
                };
            }
            Color::ONE
        },
    );
    // One invalid splat per sample, plus every sample of column 2.
    assert_eq!(r.stats.nonfinite, 6 * 5 * 8 + 5 * 8);
    let img = r.film.image();
    assert!(img.pixels.iter().all(|c| c.is_finite()));
    assert_eq!(img.get(2, 3), Color::ZERO);
    assert_eq!(img.get(3, 3), Color::ONE);
    assert_eq!(r.film.sample_count(UVec2::new(2, 3)), 8);
}

/// The closure raises the stop flag after 1000 samples: the render stops,
/// keeps exactly the samples computed, and each pixel's mean is right.
#[test]
fn interruption_keeps_every_computed_sample() {
    let stop = AtomicBool::new(false);
    let calls = AtomicU64::new(0);
    let r = render_pixels_with_stop(40, 30, &options(64, 2, 8), &stop, |_, _, _| {
        if calls.fetch_add(1, Ordering::Relaxed) + 1 == 1000 {
            stop.store(true, Ordering::Relaxed);
        }
        Color::new(1.0, 2.0, 3.0)
    });
    let calls = calls.load(Ordering::Relaxed);
    assert!(r.stats.interrupted);
    assert!((1000..40 * 30 * 64).contains(&calls));
    assert_eq!(r.stats.samples, calls);
    assert_eq!(r.film.total_samples(), calls);
    let img = r.film.image();
    for y in 0..30 {
        for x in 0..40 {
            let expected = if r.film.sample_count(UVec2::new(x, y)) > 0 {
                Color::new(1.0, 2.0, 3.0)
            } else {
                Color::ZERO
            };
            assert_eq!(img.get(x, y), expected);
        }
    }
}

/// Samples that would never end by themselves (they loop until
/// `stop_requested`) end within moments of the stop request, and are
/// dropped whole: the film holds only the samples that finished.
#[test]
fn a_stop_request_ends_a_sample_from_inside() {
    let stop = AtomicBool::new(false);
    let calls = AtomicU64::new(0);
    let start = Instant::now();
    let r = std::thread::scope(|s| {
        s.spawn(|| {
            std::thread::sleep(Duration::from_millis(100));
            stop.store(true, Ordering::Relaxed);
        });
        render_pixels_with_stop(8, 8, &options(4, 1, 4), &stop, |p, _, splats| {
            // The first 20 samples are quick; the others never end alone.
            if calls.fetch_add(1, Ordering::Relaxed) < 20 {
                return Color::ONE;
            }
            splats.push(Splat {
                raster: p.as_vec2(),
                value: Color::ONE,
            });
            while !stop::stop_requested() {
                std::hint::spin_loop();
            }
            Color::splat(1000.0)
        })
    });
    assert!(start.elapsed() < Duration::from_secs(10));
    assert!(r.stats.interrupted);
    assert_eq!(r.stats.samples, 20);
    let img = r.film.image();
    assert!(
        img.pixels
            .iter()
            .all(|&c| c == Color::ZERO || c == Color::ONE)
    );
    assert_eq!(r.film.unsampled_pixels(), 64 - 5);
    // Outside a render nothing asks to stop.
    assert!(!stop::stop_requested());
}

/// Naive recursion with N = 1000 (10¹² rays per sample) and a path
/// tracer that never ends a path in a closed white furnace both stop
/// within moments of the request, keeping no half-computed sample.
#[test]
fn endless_integrators_see_the_stop_request() {
    use raytracer::integrator::{NaiveRecursive, PathTracer};
    let naive = NaiveRecursive::new(vec![1000], Some(5));
    let endless = PathTracer {
        max_depth: None,
        rr_depth: u32::MAX,
        ..PathTracer::default()
    };
    // Inside a white sphere: no path ever escapes.
    let closed = "[camera]\nposition = [0, 0, 0]\nlook_at = [0, 0, -1]\nfov = 40\n\
                  [materials.white]\ntype = \"lambert\"\nalbedo = 1\n\
                  [[shapes]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 5\n\
                  material = \"white\"\nemission = 1\ntwo_sided = true\n";
    let closed = raytracer::scene::load_str(
        closed,
        &raytracer::scene::SceneOrigin::Dir {
            name: "closed".into(),
            dir: ".".into(),
        },
    )
    .unwrap();
    for (mut scene, integrator) in [
        (
            Scene::builtin("cornell").unwrap(),
            &naive as &dyn Integrator,
        ),
        (Scene::build("closed", closed), &endless),
    ] {
        scene.set_resolution(2, 2);
        let stop = AtomicBool::new(false);
        let start = Instant::now();
        let r = std::thread::scope(|s| {
            s.spawn(|| {
                std::thread::sleep(Duration::from_millis(200));
                stop.store(true, Ordering::Relaxed);
            });
            render_pixels_with_stop(2, 2, &options(1, 2, 2), &stop, |p, sampler, splats| {
                integrator.sample(&scene, p, sampler, splats)
            })
        });
        let seconds = start.elapsed().as_secs_f64();
        assert!(seconds < 1.2, "{}: {seconds} s", integrator.name());
        assert!(r.stats.interrupted && r.stats.samples == 0);
    }
}

#[test]
fn absurd_thread_counts_are_capped() {
    assert!(thread_limit() >= 64);
    let r = render_pixels_with_stop(
        4,
        4,
        &options(1, 1_000_000, 4),
        &AtomicBool::new(false),
        |_, _, _| Color::ONE,
    );
    assert_eq!(r.stats.samples, 16);
}

#[test]
fn memory_estimates_and_the_cap() {
    assert_eq!(memory_needed(10, 10), Some(14_300));
    assert_eq!(memory_needed(u32::MAX, u32::MAX), None);
    let cap = MemoryCap {
        bytes: 1 << 30,
        source: "a test".into(),
    };
    assert!(cap.check("a tiny image", memory_needed(64, 64)).is_ok());
    let e = cap
        .check("a 100000×100000 image", memory_needed(100_000, 100_000))
        .unwrap_err();
    assert_eq!(
        e,
        "a 100000×100000 image needs about 1332 GiB of memory, more than the cap of 1.0 GiB (a test)"
    );
    assert!(cap.check("x", None).unwrap_err().contains("2^64"));
    let here = MemoryCap::of_this_machine();
    assert!(here.bytes >= 1 << 20, "{here:?}");
}

#[test]
fn empty_renders_are_fine() {
    let stop = AtomicBool::new(false);
    let r = render_pixels_with_stop(0, 7, &options(4, 2, 4), &stop, |_, _, _| Color::ONE);
    assert_eq!(r.stats.samples, 0);
    assert!(!r.stats.interrupted);
    let r = render_pixels_with_stop(3, 3, &options(0, 1, 0), &stop, |_, _, _| Color::ONE);
    assert_eq!(r.film.image(), raytracer::film::Image::new(3, 3));
}

#[test]
fn options_from_scene_settings() {
    let settings = RenderSettings {
        spp: 7,
        seed: 9,
        ..Default::default()
    };
    let o = RenderOptions::from(&settings);
    assert_eq!((o.spp, o.seed), (7, 9));
    assert_eq!(
        RenderOptions {
            spp: 16,
            seed: 0,
            ..o
        },
        RenderOptions::default()
    );
}

#[test]
fn progress_and_summary_text() {
    assert!(ProgressStyle::with_template(&progress_template("samples")).is_ok());
    let stats = RenderStats {
        elapsed: Duration::from_millis(1500),
        samples: 3_000_000,
        interrupted: true,
        nonfinite: 2,
    };
    assert_eq!(stats.samples_per_second(), 2e6);
    let line = summary(&options(16, 2, 16), 640, 480, 2, &stats);
    assert_eq!(
        line,
        "test: 640×480, 16 spp, 3.00M samples in 1.50 s (2.00M samples/s, 2 threads), \
         INTERRUPTED, 2 NaN/inf/negative values dropped"
    );
}

const CHILD: &str = "RAYTRACER_RENDER_INTERRUPT_CHILD";

/// The global flag is shared by every render in the process, so the test
/// of [`request_interrupt`] runs in a child process (this test binary,
/// running only `global_interrupt_child`) where it disturbs no one.
#[test]
fn global_interrupt_in_a_child_process() {
    let exe = std::env::current_exe().expect("test binary path");
    let out = std::process::Command::new(exe)
        .args([
            "--exact",
            "unit::render::global_interrupt_child",
            "--ignored",
            "--test-threads=1",
        ])
        .env(CHILD, "1")
        .output()
        .expect("cannot run the test binary");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(text.contains("1 passed"), "{text}");
}

#[test]
#[ignore = "run by global_interrupt_in_a_child_process"]
fn global_interrupt_child() {
    if std::env::var_os(CHILD).is_none() {
        return;
    }
    install_interrupt_handler();
    install_interrupt_handler();
    reset_interrupt();
    assert!(!interrupted());
    let calls = AtomicU64::new(0);
    let r = render_pixels(16, 16, &options(64, 2, 8), |_, _, _| {
        if calls.fetch_add(1, Ordering::Relaxed) == 500 {
            request_interrupt();
        }
        Color::ONE
    });
    assert!(r.stats.interrupted && interrupted());
    assert_eq!(r.stats.samples, calls.load(Ordering::Relaxed));
    assert!(r.stats.samples < 16 * 16 * 64);
    reset_interrupt();
    let r = render_pixels(4, 4, &options(4, 1, 8), |_, _, _| Color::ONE);
    assert!(!r.stats.interrupted && r.stats.samples == 64);
}

/// The cost of the loop itself: a closure that does almost nothing.
/// `cargo test --release -p raytracer --lib render::tests::loop_overhead -- --ignored --nocapture`
#[test]
#[ignore = "a measurement, not a test"]
fn loop_overhead() {
    for threads in [1, 2] {
        let opts = options(256, threads, 16);
        let r = render_pixels_with_stop(512, 512, &opts, &AtomicBool::new(false), |_, s, _| {
            Color::splat(s.next_1d())
        });
        println!(
            "{threads} thread(s): {:.1} M samples/s",
            r.stats.samples_per_second() / 1e6
        );
    }
}
