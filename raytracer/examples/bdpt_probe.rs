use raytracer::integrator::render_strategies;
use raytracer::metrics::mean;
use raytracer::render::RenderOptions;
use raytracer::scene::Scene;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = &args[1];
    let d: u32 = args[2].parse().unwrap();
    let mut scene = Scene::builtin(name).unwrap();
    scene.set_resolution(16, 16);
    let o = RenderOptions {
        spp: 64,
        seed: 1,
        progress: false,
        ..Default::default()
    };
    for ((s, t), w, u) in render_strategies(&scene, &o, d) {
        println!("s={s} t={t} weighted {} unweighted {}", mean(&w), mean(&u));
    }
}
