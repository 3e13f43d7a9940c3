//! The same seed gives the same image bit for bit, whatever the thread count.

use raytracer::integrator::{AmbientOcclusion, Direct, Integrator, NaiveRecursive, PathTracer};
use raytracer::render::{RenderOptions, render};
use raytracer::scene::Scene;

fn bits(scene: &Scene, integrator: &dyn Integrator, threads: usize) -> (Vec<u32>, Vec<u32>) {
    let options = RenderOptions {
        spp: 8,
        seed: 5,
        threads: Some(threads),
        progress: false,
        ..RenderOptions::default()
    };
    let film = render(scene, integrator, &options).film;
    (film.image().bits(), film.variance_image().bits())
}

#[test]
fn images_are_identical_with_one_and_many_threads() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(48, 40);
    let naive = NaiveRecursive::new(vec![3, 2], Some(4));
    for integrator in [
        &Direct as &dyn Integrator,
        &AmbientOcclusion::default(),
        &PathTracer::default(),
        &naive,
    ] {
        let one = bits(&scene, integrator, 1);
        for threads in [2, 3] {
            assert!(
                one == bits(&scene, integrator, threads),
                "{} differs with {threads} threads",
                integrator.name()
            );
        }
    }
}

#[test]
fn exr_files_are_identical_with_one_and_two_threads() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(32, 32);
    let dir = std::env::temp_dir().join(format!("raytracer-determinism-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut files = Vec::new();
    for threads in [1, 2] {
        let options = RenderOptions {
            spp: 4,
            seed: 9,
            threads: Some(threads),
            progress: false,
            ..RenderOptions::default()
        };
        let path = dir.join(format!("t{threads}.exr"));
        render(&scene, &Direct, &options)
            .film
            .write_exr(&path)
            .unwrap();
        files.push(std::fs::read(&path).unwrap());
    }
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        files[0] == files[1],
        "EXR bytes differ between 1 and 2 threads"
    );
}

#[test]
fn a_different_seed_gives_a_different_image() {
    let mut scene = Scene::builtin("cornell").unwrap();
    scene.set_resolution(16, 16);
    let render_seed = |seed| {
        let options = RenderOptions {
            spp: 2,
            seed,
            threads: Some(1),
            progress: false,
            ..RenderOptions::default()
        };
        render(&scene, &Direct, &options).film.image().pixels
    };
    assert_ne!(render_seed(1), render_seed(2));
}
