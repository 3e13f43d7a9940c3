//! A uniform grid over a box of space: the nearest-neighbour structure of the
//! biased integrators.
//!
//! Lecture topic: photon mapping's density estimation needs "the photons near
//! x", SPPM and irradiance caching need "the visible points (records) whose
//! sphere contains x". A uniform grid of cells about as large as the search
//! radius answers both: points go into the cell that holds them and a query
//! scans the cells its search sphere touches; spheres go into every cell they
//! touch and a query reads the one cell that holds the point.
//!
//! **Why a grid and not a k-d tree.** Measured against a k-d tree crate
//! (kiddo 5), the grid builds several times faster (a counting sort) and
//! answers radius and k-nearest queries faster on photons spread over
//! surfaces; the figures and the command are in the README ("Nearest
//! neighbours"). The tree wins only for k-nearest queries in a cluster far
//! denser than the cell size (a caustic focused into a spot much smaller
//! than the search radius), where the grid scans every photon of the spot:
//! here the search radius is derived from the photons' own density, and
//! caustic maps are small. The grid also adds no dependency.
//!
//! **Determinism.** Items are ordered by a counting sort on the cell index,
//! stable in the order they were given; the build does not depend on threads.
//! Memory: one `u32` per cell plus one per (item, cell) pair; the cell count
//! is capped at [`MAX_CELLS`] by coarsening the cells.

use crate::math::Vec3A;

/// The most cells a grid allocates (16 MiB of cell starts).
pub const MAX_CELLS: usize = 1 << 22;

/// The cells of a grid, and the items each one holds (compressed rows).
#[derive(Clone, Debug)]
pub struct Grid {
    lo: Vec3A,
    cell: f32,
    dims: [usize; 3],
    /// `start[c]..start[c + 1]` indexes `items` for cell `c`.
    pub start: Vec<u32>,
    items: Vec<u32>,
}

impl Grid {
    /// An empty grid that holds nothing.
    pub fn empty() -> Grid {
        Grid {
            lo: Vec3A::ZERO,
            cell: 1.0,
            dims: [1, 1, 1],
            start: vec![0, 0],
            items: Vec::new(),
        }
    }

    /// A grid over the box `[lo, hi]` with cells of edge `cell` (made larger
    /// if the box would need more than [`MAX_CELLS`] cells), holding item `i`
    /// in every cell the box `bounds(i)` touches, for `i` in `0..n`.
    pub fn build(
        lo: Vec3A,
        hi: Vec3A,
        cell: f32,
        n: usize,
        bounds: impl Fn(usize) -> (Vec3A, Vec3A),
    ) -> Grid {
        if n == 0 || !(lo.is_finite() && hi.is_finite()) {
            return Grid::empty();
        }
        let extent = (hi - lo).max(Vec3A::splat(1e-6));
        let mut cell = cell.max(extent.max_element() * 1e-6).max(1e-7);
        let dims = loop {
            let d = (extent / cell).to_array().map(|e| (e as usize) + 1);
            if d.iter().product::<usize>() <= MAX_CELLS {
                break d;
            }
            cell *= 1.26;
        };
        let mut grid = Grid {
            lo,
            cell,
            dims,
            start: Vec::new(),
            items: Vec::new(),
        };
        let cells = dims[0] * dims[1] * dims[2];
        // Counting sort: count, prefix sums, then place in item order.
        let mut count = vec![0u32; cells + 1];
        for i in 0..n {
            let (a, b) = bounds(i);
            grid.for_cells(a, b, |c| count[c + 1] += 1);
        }
        for c in 0..cells {
            count[c + 1] += count[c];
        }
        let mut fill = count.clone();
        let mut items = vec![0u32; count[cells] as usize];
        for i in 0..n {
            let (a, b) = bounds(i);
            grid.for_cells(a, b, |c| {
                items[fill[c] as usize] = i as u32;
                fill[c] += 1;
            });
        }
        grid.start = count;
        grid.items = items;
        grid
    }

    /// The edge of a cell.
    pub fn cell_size(&self) -> f32 {
        self.cell
    }

    /// Bytes the grid holds.
    pub fn bytes(&self) -> usize {
        4 * (self.start.len() + self.items.len())
    }

    #[inline]
    fn coords(&self, p: Vec3A) -> [usize; 3] {
        let c = ((p - self.lo) / self.cell).max(Vec3A::ZERO).to_array();
        [0, 1, 2].map(|k| (c[k] as usize).min(self.dims[k] - 1))
    }

    /// Calls `f` with the index of every cell the box `[a, b]` touches.
    #[inline]
    fn for_cells(&self, a: Vec3A, b: Vec3A, mut f: impl FnMut(usize)) {
        let (c0, c1) = (self.coords(a), self.coords(b));
        for z in c0[2]..=c1[2] {
            for y in c0[1]..=c1[1] {
                let row = (z * self.dims[1] + y) * self.dims[0];
                for x in c0[0]..=c1[0] {
                    f(row + x);
                }
            }
        }
    }

    /// The items of the cell that holds `p` (empty outside the grid's box).
    #[inline]
    pub fn at(&self, p: Vec3A) -> &[u32] {
        let inside = (p - self.lo).min_element() >= 0.0
            && (p - self.lo - Vec3A::from_array(self.dims.map(|d| d as f32)) * self.cell)
                .max_element()
                <= 0.0;
        if !inside {
            return &[];
        }
        let c = self.coords(p);
        let i = (c[2] * self.dims[1] + c[1]) * self.dims[0] + c[0];
        &self.items[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// Calls `f` with every item of every cell the sphere `(p, r)` touches
    /// (an item held by several of those cells is seen several times; point
    /// items are held by one cell each).
    #[inline]
    pub fn for_each_near(&self, p: Vec3A, r: f32, mut f: impl FnMut(u32)) {
        let (c0, c1) = (
            self.coords(p - Vec3A::splat(r)),
            self.coords(p + Vec3A::splat(r)),
        );
        for z in c0[2]..=c1[2] {
            for y in c0[1]..=c1[1] {
                let row = (z * self.dims[1] + y) * self.dims[0];
                // The cells of a row are consecutive: one slice.
                let (s, e) = (self.start[row + c0[0]], self.start[row + c1[0] + 1]);
                for &i in &self.items[s as usize..e as usize] {
                    f(i);
                }
            }
        }
    }
}
