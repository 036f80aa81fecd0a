//! The machine's own ceiling for a frame on several threads: a plain parallel loop over a frame's memory.
//!
//! Each pixel's colour and depth are written from its index (a multiply each, nothing read), the frame cut into
//! as many bands of rows as there are threads, each band on a thread of a pool started once, as the scene
//! renderer's are. A fill writes the frame [`Ceiling::passes`] times, at least [`MIN_WRITES`] pixels, so that
//! a small frame's fill lasts long enough to time. Timed on one thread and on several, taking turns, its speed-up
//! is what this machine gives that memory traffic when more threads share it: a frame's speed-up over its threads
//! is compared with it.

use rayon_core::{ThreadPool, ThreadPoolBuilder};

/// The fewest pixels a fill writes, over as many passes over the frame as that takes.
pub const MIN_WRITES: usize = 1 << 23;

/// A frame's colour and depth buffers and the threads that fill them.
pub struct Ceiling {
    color: Vec<u32>,
    depth: Vec<f32>,
    /// Pixels of a band: whole rows, one band per thread.
    band: usize,
    /// The threads beside the caller; `None` for one thread.
    pool: Option<ThreadPool>,
    passes: usize,
}

impl Ceiling {
    /// Buffers of `width x height` pixels filled on `threads` threads (the caller's and `threads - 1` more).
    ///
    /// # Errors
    /// When the system refuses to start the threads.
    pub fn new(width: u32, height: u32, threads: usize) -> Result<Self, String> {
        let threads = threads.max(1);
        let pool = if threads > 1 {
            let pool = ThreadPoolBuilder::new().num_threads(threads - 1).build().map_err(|e| e.to_string())?;
            Some(pool)
        } else {
            None
        };
        let n = width as usize * height as usize;
        let band = (height as usize).div_ceil(threads).max(1) * (width as usize).max(1);
        let passes = MIN_WRITES.div_ceil(n.max(1));
        Ok(Self { color: vec![0; n], depth: vec![1.0; n], band, pool, passes })
    }

    /// How many times a fill writes the frame.
    pub fn passes(&self) -> usize {
        self.passes
    }

    /// Writes every pixel of the frame [`Self::passes`] times, in bands of rows, one band per thread.
    pub fn fill(&mut self) {
        let (passes, band) = (self.passes, self.band);
        let bands = self.color.chunks_mut(band).zip(self.depth.chunks_mut(band)).enumerate();
        match &self.pool {
            Some(pool) => pool.in_place_scope(|scope| {
                let mut bands = bands;
                let own = bands.next();
                for (i, (color, depth)) in bands {
                    scope.spawn(move |_| write_band(i * band, color, depth, passes));
                }
                if let Some((i, (color, depth))) = own {
                    write_band(i * band, color, depth, passes);
                }
            }),
            None => {
                for (i, (color, depth)) in bands {
                    write_band(i * band, color, depth, passes);
                }
            }
        }
    }

    /// The frame's colour buffer, so that the writes cannot be left out.
    pub fn pixels(&self) -> &[u32] {
        &self.color
    }
}

/// Writes pixels `first..first + color.len()` `passes` times: a colour and a depth from each one's index.
fn write_band(first: usize, color: &mut [u32], depth: &mut [f32], passes: usize) {
    for _ in 0..passes {
        for (i, (c, d)) in color.iter_mut().zip(depth.iter_mut()).enumerate() {
            let index = (first + i) as u32;
            *c = index.wrapping_mul(0x9E37_79B9) >> 8;
            *d = index as f32 * 1e-7;
        }
        std::hint::black_box(&mut *color);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pixel is written, with the value of its index, whatever the number of threads and bands.
    #[test]
    fn every_pixel_is_written_once_per_fill() {
        for threads in [1, 2, 3, 7] {
            let mut ceiling = Ceiling::new(13, 11, threads).expect("threads");
            assert_eq!(ceiling.passes(), MIN_WRITES.div_ceil(13 * 11));
            ceiling.fill();
            for (i, &c) in ceiling.pixels().iter().enumerate() {
                assert_eq!(c, (i as u32).wrapping_mul(0x9E37_79B9) >> 8, "{threads} threads, pixel {i}");
            }
            assert!(ceiling.depth.iter().enumerate().all(|(i, &d)| d == i as f32 * 1e-7));
        }
    }
}
