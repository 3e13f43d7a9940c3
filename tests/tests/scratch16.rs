use grading::compare::*;
#[test]
#[ignore]
fn make_reference() {
    let t = std::time::Instant::now();
    render_reference(&EX16_DOOR, false).unwrap();
    println!("{:?}", t.elapsed());
}
#[test]
#[ignore]
fn door_seeds() {
    let chain = grading::exercises::ex16_metropolis::metropolis_chain;
    let t = std::time::Instant::now();
    grading::ex16_metropolis::check(chain).unwrap();
    println!("whole check {:?}", t.elapsed());
    for seed in 0..40 {
        let t = std::time::Instant::now();
        let z = grading::ex16_metropolis::door_max_t(chain, 1000 + seed);
        println!("seed {seed}: {:?} {:?}", z, t.elapsed());
    }
}
