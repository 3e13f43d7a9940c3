use grading::ex17_photon_mapping as g;
use exercises::ex17_photon_mapping as s;
use std::time::Instant;
#[test]
fn timing() {
    let t = Instant::now();
    g::check_estimate(s::photon_radiance).unwrap();
    eprintln!("estimate {:?}", t.elapsed());
    let t = Instant::now();
    g::check_tracing(s::trace_photon_path).unwrap();
    eprintln!("tracing {:?}", t.elapsed());
    let t = Instant::now();
    g::check_furnace(s::trace_photon_path, s::photon_radiance).unwrap();
    eprintln!("furnace {:?}", t.elapsed());
    eprintln!("t {}", g::t_quantile(15, 1e-4/96.0));
}
