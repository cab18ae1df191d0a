//! 10-point Gauss–Legendre quadrature on [a, b] (exact for polynomials up to degree 19).

const NODES: [f64; 5] = [0.148_874_338_981_631_2, 0.433_395_394_129_247_2, 0.679_409_568_299_024_4, 0.865_063_366_688_984_5, 0.973_906_528_517_171_7];
const WEIGHTS: [f64; 5] = [0.295_524_224_714_752_9, 0.269_266_719_309_996_3, 0.219_086_362_515_982, 0.149_451_349_150_580_6, 0.066_671_344_308_688_1];

/// ∫_a^b f(u) du for a vector-valued integrand of two components.
pub fn integrate2(a: f64, b: f64, f: impl Fn(f64) -> (f64, f64)) -> (f64, f64) {
    let mid = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let (mut sx, mut sy) = (0.0, 0.0);
    for (x, w) in NODES.iter().zip(WEIGHTS.iter()) {
        let (ax, ay) = f(mid - half * x);
        let (bx, by) = f(mid + half * x);
        sx += w * (ax + bx);
        sy += w * (ay + by);
    }
    (sx * half, sy * half)
}

/// ∫_a^b f(u) du for a scalar integrand.
pub fn integrate(a: f64, b: f64, f: impl Fn(f64) -> f64) -> f64 {
    integrate2(a, b, |u| (f(u), 0.0)).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_degree_19_polynomials() {
        // ∫_0^2 u^k du = 2^(k+1)/(k+1)
        for k in 0..20 {
            let got = integrate(0.0, 2.0, |u| u.powi(k));
            let want = 2f64.powi(k + 1) / f64::from(k + 1);
            assert!((got - want).abs() <= 1e-13 * want, "k={k}: {got} vs {want}");
        }
    }
}
