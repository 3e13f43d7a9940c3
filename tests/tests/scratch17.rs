use grading::ex17_photon_mapping as g;
use exercises::ex17_photon_mapping as s;
use std::time::Instant;
#[test]
fn timing() {
    let t = Instant::now();
    g::render_reference(false).unwrap();
    eprintln!("reference {:?}", t.elapsed());
    for seed in 0..25u64 {
        let t = Instant::now();
        let mut z = 0.0;
        let r = g::compare_caustic_z(s::trace_photon_path, s::photon_radiance, 1000 * seed + 11, Some(&mut z));
        eprintln!("seed {seed}: z/thr {z:.3} {:?} {:?}", t.elapsed(), r.err());
    }
    let t = Instant::now();
    grading::ex17_photon_mapping::check(s::trace_photon_path, s::photon_radiance).unwrap();
    eprintln!("whole check {:?}", t.elapsed());
}
