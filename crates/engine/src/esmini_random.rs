//! esmini's global random generator, reproduced bit for bit so that the choices esmini leaves
//! to chance come out the same for the same seed (esmini's `--seed`; the reference traces were
//! made with `--seed 0`).
//!
//! esmini keeps one `std::mt19937` for the whole run (`SE_Env::Inst().GetRand()`), seeded once
//! before the scenario is loaded. What it draws is shaped by libstdc++'s distributions, which
//! are reproduced here too:
//! - `GetNumberBetween(a, b)` is `std::uniform_int_distribution<int>{a, b}`: for a range that
//!   fits in 32 bits, libstdc++ multiplies one 32-bit output by the range size in 64 bits and
//!   keeps the high word (Lemire's method), redrawing only in the rare biased low zone;
//! - `GetReal()` is `std::uniform_real_distribution<double>{0, 1}`, i.e. `generate_canonical`
//!   with 53 bits: two 32-bit outputs `(lo + hi·2³²) / 2⁶⁴`, kept below 1.
//!
//! The engine draws where esmini draws and in the same order (see `roads::road_follow` for the
//! junction tie-break, today the only draw that touches a compared trace).

/// The seed esmini's reference traces were made with (`esmini --seed 0`).
pub const DEFAULT_SEED: u32 = 0;

const N: usize = 624;
const M: usize = 397;
const MATRIX_A: u32 = 0x9908_b0df;
const UPPER: u32 = 0x8000_0000;
const LOWER: u32 = 0x7fff_ffff;

/// The 32-bit Mersenne Twister MT19937 (Matsumoto & Nishimura 1998), seeded like
/// `std::mt19937(seed)`.
#[derive(Clone)]
pub struct Mt19937 {
    state: [u32; N],
    index: usize,
}

impl Mt19937 {
    pub fn new(seed: u32) -> Mt19937 {
        let mut state = [0u32; N];
        state[0] = seed;
        for i in 1..N {
            let prev = state[i - 1];
            state[i] = 1_812_433_253u32.wrapping_mul(prev ^ (prev >> 30)).wrapping_add(i as u32);
        }
        Mt19937 { state, index: N }
    }

    /// The next 32-bit output.
    pub fn next_u32(&mut self) -> u32 {
        if self.index >= N {
            self.twist();
        }
        let mut y = self.state[self.index];
        self.index += 1;
        y ^= y >> 11;
        y ^= (y << 7) & 0x9d2c_5680;
        y ^= (y << 15) & 0xefc6_0000;
        y ^ (y >> 18)
    }

    fn twist(&mut self) {
        for i in 0..N {
            let y = (self.state[i] & UPPER) | (self.state[(i + 1) % N] & LOWER);
            let mut v = self.state[(i + M) % N] ^ (y >> 1);
            if y & 1 != 0 {
                v ^= MATRIX_A;
            }
            self.state[i] = v;
        }
        self.index = 0;
    }
}

impl std::fmt::Debug for Mt19937 {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Mt19937").field("index", &self.index).finish_non_exhaustive()
    }
}

/// esmini's `SE_Rand`: the generator and the two ways esmini draws from it.
#[derive(Debug, Clone)]
pub struct EsminiRandom {
    mt: Mt19937,
    draws: u64,
}

impl EsminiRandom {
    pub fn new(seed: u32) -> EsminiRandom {
        EsminiRandom { mt: Mt19937::new(seed), draws: 0 }
    }

    /// 32-bit outputs taken so far (for tests and diagnostics).
    pub fn outputs_used(&self) -> u64 {
        self.draws
    }

    fn next(&mut self) -> u32 {
        self.draws += 1;
        self.mt.next_u32()
    }

    /// An integer in `min..=max` (esmini's `GetNumberBetween`; `min` when `max < min`).
    pub fn number_between(&mut self, min: i32, max: i32) -> i32 {
        if max < min {
            return min;
        }
        let span = (max as i64 - min as i64) as u64; // 0 ..= 2^32 - 1
        if span == u32::MAX as u64 {
            // The whole 32-bit range: one output, no scaling.
            return (min as i64 + self.next() as i64) as i32;
        }
        let range = span + 1; // fits in 32 bits here
        let mut product = self.next() as u64 * range;
        let mut low = product & 0xffff_ffff;
        if low < range {
            // Reject the few outputs that would bias the result.
            let threshold = (1u64 << 32).wrapping_sub(range) % range;
            while low < threshold {
                product = self.next() as u64 * range;
                low = product & 0xffff_ffff;
            }
        }
        (min as i64 + (product >> 32) as i64) as i32
    }

    /// A real number in [0, 1) (esmini's `GetReal`).
    pub fn real(&mut self) -> f64 {
        let lo = self.next() as f64;
        let hi = self.next() as f64;
        let two32 = 4_294_967_296.0;
        let r = (lo + hi * two32) / (two32 * two32);
        if r >= 1.0 {
            1.0 - f64::EPSILON / 2.0
        } else {
            r
        }
    }
}

impl Default for EsminiRandom {
    fn default() -> Self {
        EsminiRandom::new(DEFAULT_SEED)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ten_thousandth_output_of_the_default_seed() {
        // The C++ standard ([rand.predef]): a default-constructed mt19937 (seed 5489) yields
        // 4123659995 as its 10000th output.
        let mut mt = Mt19937::new(5489);
        for _ in 0..9999 {
            mt.next_u32();
        }
        assert_eq!(mt.next_u32(), 4_123_659_995);
    }

    #[test]
    fn first_output_of_seed_5489() {
        // Matsumoto & Nishimura's reference output for init_genrand(5489).
        assert_eq!(Mt19937::new(5489).next_u32(), 3_499_211_612);
    }

    #[test]
    fn coin_is_the_top_bit_of_one_output() {
        // range 2: (x · 2) >> 32 is x's top bit, and no output is ever rejected.
        let mut mt = Mt19937::new(7);
        let mut r = EsminiRandom::new(7);
        for _ in 0..1000 {
            let x = mt.next_u32();
            assert_eq!(r.number_between(0, 1), (x >> 31) as i32);
        }
        assert_eq!(r.outputs_used(), 1000);
    }

    #[test]
    fn real_uses_two_outputs_low_word_first() {
        let mut mt = Mt19937::new(3);
        let (lo, hi) = (mt.next_u32() as f64, mt.next_u32() as f64);
        let mut r = EsminiRandom::new(3);
        let want = (lo + hi * 4_294_967_296.0) / 18_446_744_073_709_551_616.0;
        assert_eq!(r.real(), want);
        assert_eq!(r.outputs_used(), 2);
    }

    #[test]
    fn number_between_stays_in_range() {
        let mut r = EsminiRandom::new(11);
        for _ in 0..10_000 {
            let v = r.number_between(-3, 4);
            assert!((-3..=4).contains(&v));
        }
        assert_eq!(r.number_between(5, 2), 5);
        let _ = r.number_between(i32::MIN, i32::MAX);
    }
}
