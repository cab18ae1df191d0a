//! Loads one OpenDRIVE file N times (for profiling `opendrive::load`).
//! Run: cargo run --release -p osc2cr-opendrive --example load_repeat -- FILE [N]

fn main() {
    let mut args = std::env::args().skip(1);
    let Some(file) = args.next() else {
        eprintln!("usage: load_repeat FILE [N]");
        return;
    };
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(20);
    let mut times = Vec::with_capacity(n);
    for _ in 0..n {
        let t0 = std::time::Instant::now();
        match opendrive::load(&file) {
            Ok(l) => std::hint::black_box(l),
            Err(e) => {
                eprintln!("{e}");
                return;
            }
        };
        times.push(t0.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    let median = times.get(times.len() / 2).copied().unwrap_or(f64::NAN);
    println!("{n} loads of {file}: median {median:.3} ms, min {:.3} ms", times.first().copied().unwrap_or(f64::NAN));
}
