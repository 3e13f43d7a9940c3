//! Piecewise-constant distributions: choose an index (or a point in `[0,1)²`)
//! with probability proportional to tabulated weights. Used to pick a light
//! by its power and to sample an environment map by its brightness.

use crate::math::Vec2;

/// A piecewise-constant density on `[0, 1)` with `n` equal cells.
#[derive(Clone, Debug)]
pub struct Distribution1D {
    func: Vec<f32>,
    cdf: Vec<f32>,
    integral: f32,
}

impl Distribution1D {
    /// From non-negative cell weights. If all are zero, the density is uniform.
    pub fn new(weights: &[f32]) -> Self {
        assert!(
            !weights.is_empty(),
            "a distribution needs at least one cell"
        );
        let n = weights.len();
        let func: Vec<f32> = weights
            .iter()
            .map(|w| if w.is_finite() { w.max(0.0) } else { 0.0 })
            .collect();
        let mut cdf = Vec::with_capacity(n + 1);
        cdf.push(0.0f32);
        let mut acc = 0.0f64;
        for f in &func {
            acc += *f as f64 / n as f64;
            cdf.push(acc as f32);
        }
        let integral = acc as f32;
        if integral > 0.0 {
            for c in cdf.iter_mut() {
                *c /= integral;
            }
        } else {
            for (i, c) in cdf.iter_mut().enumerate() {
                *c = i as f32 / n as f32;
            }
        }
        *cdf.last_mut().unwrap() = 1.0;
        Distribution1D {
            func,
            cdf,
            integral,
        }
    }

    pub fn len(&self) -> usize {
        self.func.len()
    }

    pub fn is_empty(&self) -> bool {
        self.func.is_empty()
    }

    /// The integral of the weights over `[0, 1)` (their mean).
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// Picks a cell: returns its index and its probability.
    #[inline]
    pub fn sample_discrete(&self, u: f32) -> (usize, f32) {
        let i = self.find(u);
        (i, self.discrete_pdf(i))
    }

    /// Probability of choosing cell `i` by [`Self::sample_discrete`].
    #[inline]
    pub fn discrete_pdf(&self, i: usize) -> f32 {
        self.cdf[i + 1] - self.cdf[i]
    }

    /// A continuous sample in `[0, 1)`: returns `x`, its density and its cell.
    #[inline]
    pub fn sample_continuous(&self, u: f32) -> (f32, f32, usize) {
        let i = self.find(u);
        let width = self.cdf[i + 1] - self.cdf[i];
        let du = if width > 0.0 {
            (u - self.cdf[i]) / width
        } else {
            0.5
        };
        let x = ((i as f32 + du.clamp(0.0, 1.0)) / self.len() as f32).min(1.0 - f32::EPSILON);
        (x, self.pdf(x), i)
    }

    /// Density of `x ∈ [0, 1)` under [`Self::sample_continuous`].
    #[inline]
    pub fn pdf(&self, x: f32) -> f32 {
        let i = ((x * self.len() as f32) as usize).min(self.len() - 1);
        if self.integral > 0.0 {
            self.func[i] / self.integral
        } else {
            1.0
        }
    }

    fn find(&self, u: f32) -> usize {
        // The last cell whose cdf start is <= u (skipping empty cells).
        let i = self.cdf.partition_point(|&c| c <= u);
        i.saturating_sub(1).min(self.len() - 1)
    }
}

/// A piecewise-constant density on `[0,1)²`: a marginal over rows `v` and a
/// conditional over columns `u` in each row.
#[derive(Clone, Debug)]
pub struct Distribution2D {
    conditional: Vec<Distribution1D>,
    marginal: Distribution1D,
}

impl Distribution2D {
    /// From `nu × nv` weights in row-major order (row = v).
    pub fn new(weights: &[f32], nu: usize, nv: usize) -> Self {
        assert_eq!(weights.len(), nu * nv, "weights must be nu × nv");
        let conditional: Vec<Distribution1D> =
            weights.chunks(nu).map(Distribution1D::new).collect();
        let marginal =
            Distribution1D::new(&conditional.iter().map(|d| d.integral()).collect::<Vec<_>>());
        Distribution2D {
            conditional,
            marginal,
        }
    }

    /// A point in `[0,1)²` and its density.
    #[inline]
    pub fn sample(&self, u: Vec2) -> (Vec2, f32) {
        let (v, pdf_v, row) = self.marginal.sample_continuous(u.y);
        let (x, pdf_u, _) = self.conditional[row].sample_continuous(u.x);
        (Vec2::new(x, v), pdf_u * pdf_v)
    }

    /// Density of the point `p ∈ [0,1)²`.
    #[inline]
    pub fn pdf(&self, p: Vec2) -> f32 {
        let row = ((p.y * self.conditional.len() as f32) as usize).min(self.conditional.len() - 1);
        self.marginal.pdf(p.y) * self.conditional[row].pdf(p.x)
    }
}
