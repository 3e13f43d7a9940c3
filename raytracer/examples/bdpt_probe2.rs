use raytracer::integrator::{Bdpt, Integrator, LightTracer, PathTracer};
use raytracer::metrics::{mean, z_test, z_threshold};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let size: u32 = args[1].parse().unwrap();
    let spp: u32 = args[2].parse().unwrap();
    let d: Option<u32> = args[3].parse().ok();
    let mut scene = Scene::builtin(&args[4]).unwrap();
    scene.set_resolution(size, size);
    let o = RenderOptions {
        spp,
        seed: 1,
        progress: false,
        ..Default::default()
    };
    let pt = PathTracer {
        max_depth: d,
        ..Default::default()
    };
    let lt = LightTracer {
        max_depth: d,
        rr_depth: 5,
    };
    let bd = Bdpt {
        max_depth: d,
        ..Default::default()
    };
    let ints: [&dyn Integrator; 3] = [&pt, &lt, &bd];
    let mut films = vec![];
    for i in ints {
        let t = std::time::Instant::now();
        let f = render(&scene, i, &o).film;
        println!(
            "{}: mean {} in {:?}",
            i.name(),
            mean(&f.image()),
            t.elapsed()
        );
        films.push(f);
    }
    let tiles = (size / 8) * (size / 8);
    println!("threshold {}", z_threshold(tiles as usize * 3, 1e-4));
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        let z = z_test(
            &films[a].image(),
            &films[a].variance_image(),
            &films[b].image(),
            &films[b].variance_image(),
            8,
        );
        println!("{a} vs {b}: max |z| {} at {:?}", z.max_abs_z, z.worst_tile);
    }
}
