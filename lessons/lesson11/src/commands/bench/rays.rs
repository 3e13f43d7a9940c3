//! Ray-throughput benchmark of the BVH: primary rays on an icosphere, the
//! case of `raytracer/tests/data/embree_bench.py` and `mitsuba_raycast.py`
//! (Embree 4 and Mitsuba 3 on the same mesh and rays), and a large mesh
//! loaded from an OBJ file.
//!
//! Camera at (0, 0, 3) looking down −z, vertical field of view 40°, 1000 × 1000
//! rays through the pixel centres: for pixel (i, j), `s_k = (k + ½)/1000·2 − 1`
//! and the direction is `normalize(s_i·tan 20°, −s_j·tan 20°, −1)`. Ray
//! generation is not timed (as in the references); each figure is the best of
//! a few repetitions. Ctrl-C is seen between chunks of [`CHUNK`] rays
//! (about a millisecond each): the repetitions left are skipped and no
//! figure is printed.

use std::sync::Arc;
use std::time::Instant;

use anyhow::Context as _;
use rayon::prelude::*;
use raytracer::geometry::stream::RayStream;
use raytracer::geometry::{Geometry, Hit, Mesh, Shape};
use raytracer::math::{Ray, Vec3A};
use raytracer::render::interrupted;

use super::interrupted::stop_if_interrupted;

const RES: usize = 1000;
const REPS: usize = 5;
/// Rays per parallel task.
const CHUNK: usize = 4096;

/// The reference camera's rays, row by row.
fn camera_rays() -> Vec<Ray> {
    let t = 20f64.to_radians().tan();
    let s = |k: usize| (k as f64 + 0.5) / RES as f64 * 2.0 - 1.0;
    let o = Vec3A::new(0.0, 0.0, 3.0);
    let mut rays = Vec::with_capacity(RES * RES);
    for j in 0..RES {
        for i in 0..RES {
            let (x, y, z) = (s(i) * t, -s(j) * t, -1.0);
            let len = (x * x + y * y + z * z).sqrt();
            let d = Vec3A::new((x / len) as f32, (y / len) as f32, (z / len) as f32);
            rays.push(Ray::new(o, d));
        }
    }
    rays
}

/// The same rays grouped in packets of 2×2 pixels (`N = 4`) or of 4×4
/// pixels made of four 2×2 groups (`N = 16`).
fn packets<const N: usize>(rays: &[Ray]) -> Vec<[Ray; N]> {
    let side = if N == 16 { 4 } else { 2 };
    let mut out = Vec::with_capacity(rays.len() / N);
    for j in (0..RES).step_by(side) {
        for i in (0..RES).step_by(side) {
            out.push(std::array::from_fn(|k| {
                // k = 4·group + lane; groups and lanes both run over 2×2.
                let (group, lane) = (k / 4, k % 4);
                let di = 2 * (group % 2) + lane % 2;
                let dj = 2 * (group / 2) + lane / 2;
                rays[(j + dj) * RES + i + di]
            }));
        }
    }
    out
}

/// CPU time of the calling thread in seconds (Linux: `/proc/thread-self/schedstat`,
/// whose first field is nanoseconds on a CPU), to see through a busy machine.
fn thread_cpu_time() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(s.split_whitespace().next()?.parse::<f64>().ok()? * 1e-9)
}

/// Best wall time (and best thread CPU time, if known) of `REPS` runs of
/// `f`, and the last result. `f` runs on one worker of `pool`.
fn best_of<R: Send>(
    pool: &rayon::ThreadPool,
    mut f: impl FnMut() -> R + Send,
) -> (f64, Option<f64>, R) {
    let (mut wall, mut cpu) = (f64::INFINITY, f64::INFINITY);
    let mut out = None;
    for rep in 0..REPS {
        // After Ctrl-C the result is not printed: one run is enough.
        if rep > 0 && interrupted() {
            break;
        }
        let (w, c, r) = pool.install(|| {
            let c0 = thread_cpu_time();
            let t = Instant::now();
            let r = f();
            let w = t.elapsed().as_secs_f64();
            (w, thread_cpu_time().zip(c0).map(|(b, a)| b - a), r)
        });
        wall = wall.min(w);
        cpu = cpu.min(c.unwrap_or(f64::INFINITY));
        out = Some(r);
    }
    (wall, cpu.is_finite().then_some(cpu), out.expect("REPS > 0"))
}

/// Closest-hit or any-hit throughput in rays per second (wall clock, and per
/// CPU second of the thread for one thread), and the hit count.
fn throughput(
    pool: &rayon::ThreadPool,
    g: &Geometry,
    rays: &[Ray],
    any_hit: bool,
) -> (f64, Option<f64>, usize) {
    let (wall, cpu, hits) = best_of(pool, || {
        rays.par_chunks(CHUNK)
            .map(|chunk| {
                if interrupted() {
                    0
                } else if any_hit {
                    chunk.iter().filter(|r| g.occluded(r)).count()
                } else {
                    // Summing t keeps the hit record alive for the optimizer.
                    let mut n = 0;
                    let mut sum = 0.0f32;
                    for r in chunk {
                        if let Some(h) = g.intersect(r) {
                            n += 1;
                            sum += h.t;
                        }
                    }
                    std::hint::black_box(sum);
                    n
                }
            })
            .sum::<usize>()
    });
    let n = rays.len() as f64;
    let single = pool.current_num_threads() == 1;
    (n / wall, cpu.filter(|_| single).map(|c| n / c), hits)
}

/// Closest-hit throughput of packets traced by `trace`.
fn throughput_packets<const N: usize>(
    pool: &rayon::ThreadPool,
    packets: &[[Ray; N]],
    trace: impl Fn(&[Ray; N]) -> [Option<Hit>; N] + Sync,
) -> (f64, Option<f64>, usize) {
    let (wall, cpu, hits) = best_of(pool, || {
        packets
            .par_chunks((CHUNK / N).max(1))
            .map(|chunk| {
                if interrupted() {
                    return 0;
                }
                let mut n = 0;
                let mut sum = 0.0f32;
                for p in chunk {
                    for h in trace(p).iter().flatten() {
                        n += 1;
                        sum += h.t;
                    }
                }
                std::hint::black_box(sum);
                n
            })
            .sum::<usize>()
    });
    let n = (N * packets.len()) as f64;
    let single = pool.current_num_threads() == 1;
    (n / wall, cpu.filter(|_| single).map(|c| n / c), hits)
}

/// Closest-hit throughput of streams of `CHUNK` rays traced together
/// (`Geometry::intersect_stream`, as the wavefront engine traces).
fn throughput_streams(
    pool: &rayon::ThreadPool,
    g: &Geometry,
    rays: &[Ray],
) -> (f64, Option<f64>, usize) {
    let (wall, cpu, hits) = best_of(pool, || {
        rays.par_chunks(CHUNK)
            .map_init(
                || (RayStream::default(), Vec::new()),
                |(stream, out), chunk| {
                    g.intersect_stream(chunk, out, stream);
                    let sum: f32 = out.iter().flatten().map(|h| h.t).sum();
                    std::hint::black_box(sum);
                    out.iter().flatten().count()
                },
            )
            .sum::<usize>()
    });
    let n = rays.len() as f64;
    let single = pool.current_num_threads() == 1;
    (n / wall, cpu.filter(|_| single).map(|c| n / c), hits)
}

/// A number with 3 significant digits.
fn sig3(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.digits$}")
}

fn measure(name: &str, g: &Geometry, rays: &[Ray], threads: &[usize]) -> anyhow::Result<()> {
    let packets4 = packets::<4>(rays);
    let packets16 = packets::<16>(rays);
    let per_cpu = |x: Option<f64>| x.map_or(String::new(), |c| format!(" ({})", sig3(c / 1e6)));
    for &n in threads {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .context("cannot start the thread pool")?;
        let (closest, closest_cpu, hits) = throughput(&pool, g, rays, false);
        let (any, any_cpu, hits_any) = throughput(&pool, g, rays, true);
        let (p4, p4_cpu, hits4) = throughput_packets(&pool, &packets4, |p| g.intersect4(p));
        let (p16, p16_cpu, hits16) = throughput_packets(&pool, &packets16, |p| g.intersect16(p));
        let (st, st_cpu, hits_stream) = throughput_streams(&pool, g, rays);
        stop_if_interrupted(false)?;
        anyhow::ensure!(
            hits == hits_any && hits == hits4 && hits == hits16 && hits == hits_stream,
            "single rays, any-hit, packets and streams disagree: {hits}, {hits_any}, {hits4}, {hits16}, {hits_stream} hits"
        );
        crate::console::say!(
            "  {name:<20} {n:>2} thread(s): closest {:>5}{}, any {:>5}{}, packets 2x2 {:>5}{}, 4x4 {:>5}{}, streams of {CHUNK} {:>5}{}; hits {hits} ({}%)",
            sig3(closest / 1e6),
            per_cpu(closest_cpu),
            sig3(any / 1e6),
            per_cpu(any_cpu),
            sig3(p4 / 1e6),
            per_cpu(p4_cpu),
            sig3(p16 / 1e6),
            per_cpu(p16_cpu),
            sig3(st / 1e6),
            per_cpu(st_cpu),
            sig3(100.0 * hits as f64 / rays.len() as f64),
        );
    }
    Ok(())
}

fn build(mesh: Mesh) -> anyhow::Result<(f64, Geometry)> {
    let mesh = Arc::new(mesh);
    let pool = rayon::ThreadPoolBuilder::new()
        .build()
        .context("cannot start the thread pool")?;
    let (wall, _, g) = best_of(&pool, || Geometry::new(vec![Shape::Mesh(mesh.clone())]));
    Ok((wall, g))
}

/// Runs the benchmark for each thread count in `threads` (an empty list means
/// 1 and all threads) and prints a table.
pub fn run(threads: &[usize]) -> anyhow::Result<()> {
    let all = std::thread::available_parallelism().map_or(1, |n| n.get());
    let threads: Vec<usize> = if threads.is_empty() {
        let mut t = vec![1, all];
        t.dedup();
        t
    } else {
        threads.to_vec()
    };
    crate::console::say!(
        "ray throughput: {RES}x{RES} primary rays, camera (0,0,3) -> -z, fov 40 deg; machine threads: {all}"
    );
    crate::console::say!(
        "Mrays/s, best of {REPS}; in parentheses: per CPU-second of the thread (a busy machine does not lower it)"
    );
    crate::console::say!(
        "closest = Geometry::intersect, any = occluded, packets = intersect4 / intersect16, streams = intersect_stream (closest hit)"
    );
    crate::console::say!(
        "reference, case (a): Mitsuba 3 llvm_ad_rgb 9.4-10.0 Mrays/s on 1 thread, 18.3 on 2; Embree 4 single rays 6-7"
    );
    let rays = camera_rays();

    // (a) The reference case: icosphere level 6.
    let ico = Mesh::icosphere(6);
    let tris = ico.indices.len();
    let (build_s, g) = build(ico)?;
    stop_if_interrupted(false)?;
    crate::console::say!(
        "(a) icosphere level 6: {tris} triangles, {} BVH nodes, build {} s",
        g.node_count(),
        sig3(build_s)
    );
    measure("icosphere 81,920", &g, &rays, &threads)?;
    drop(g);

    // (b) A large mesh through the OBJ loader: icosphere level 8.
    let big = Mesh::icosphere(8);
    stop_if_interrupted(false)?;
    let tris = big.indices.len();
    let path = std::env::temp_dir().join(format!("lesson11_bench_ico8_{}.obj", std::process::id()));
    std::fs::write(&path, big.to_obj_string())
        .with_context(|| format!("cannot write {}", path.display()))?;
    drop(big);
    let t = Instant::now();
    let loaded = Mesh::load_obj(&path);
    let load_s = t.elapsed().as_secs_f64();
    let size = std::fs::metadata(&path).map_or(0, |m| m.len());
    let _ = std::fs::remove_file(&path);
    let loaded = loaded?;
    stop_if_interrupted(false)?;
    anyhow::ensure!(
        loaded.indices.len() == tris,
        "the OBJ round trip lost triangles"
    );
    let (build_s, g) = build(loaded)?;
    stop_if_interrupted(false)?;
    crate::console::say!(
        "(b) icosphere level 8 via OBJ ({} MB): {tris} triangles, load {} s, {} BVH nodes, build {} s",
        sig3(size as f64 / 1e6),
        sig3(load_s),
        g.node_count(),
        sig3(build_s)
    );
    measure("icosphere 1,310,720", &g, &rays, &threads)?;
    Ok(())
}
