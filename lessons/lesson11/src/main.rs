mod bench_rays;

// Temporary entry point of the geometry branch: `lesson11 bench-rays [1,2]`.
// The lead wires the final command line.
fn main() -> anyhow::Result<()> {
    let mut args = std::env::args().skip(1);
    if args.next().as_deref() == Some("bench-rays") {
        let threads: Vec<usize> = match args.next() {
            Some(list) => list
                .split(',')
                .map(|t| t.trim().parse())
                .collect::<Result<_, _>>()?,
            None => Vec::new(),
        };
        return bench_rays::run(&threads);
    }
    Ok(())
}
