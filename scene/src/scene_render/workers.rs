//! The threads a renderer draws on: started once with the renderer and kept, so that a frame's passes hand their
//! jobs to threads that are already running instead of starting new ones for each pass.

use std::sync::Mutex;

use rayon_core::{ThreadPool, ThreadPoolBuilder};

/// The calling thread and a pool of `threads - 1` more, kept for the renderer's life.
///
/// A pass's jobs are taken in turn: each thread takes the next job not yet taken until none is left, so a long job
/// does not hold back the short ones queued after it.
#[derive(Debug)]
pub(crate) struct Workers {
    /// The threads beside the caller; `None` for one thread (or when the system would not start more).
    pool: Option<ThreadPool>,
    threads: usize,
}

impl Workers {
    /// The calling thread and `threads - 1` more (`threads` at least 1). When the system refuses to start them, the
    /// work runs on the calling thread alone: the same results, more slowly.
    pub fn new(threads: usize) -> Self {
        let threads = threads.max(1);
        let pool = (threads > 1)
            .then(|| {
                ThreadPoolBuilder::new()
                    .num_threads(threads - 1)
                    .thread_name(|i| format!("rastty-render-{i}"))
                    .build()
                    .ok()
            })
            .flatten();
        let threads = if pool.is_some() { threads } else { 1 };
        Self { pool, threads }
    }

    /// How many threads run a pass's jobs, the caller's included.
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// Runs `work` on every job, on up to [`Self::threads`] threads, and returns the results in the jobs' order.
    pub fn run<J: Send, T: Send>(&self, jobs: Vec<J>, work: impl Fn(J) -> T + Sync) -> Vec<T> {
        let count = jobs.len();
        let queue = Mutex::new(jobs.into_iter().enumerate());
        let results = Mutex::new(Vec::with_capacity(count));
        let worker = || {
            // The lock is held only to take a job; a poisoned lock means a worker panicked, which the scope
            // below resumes on this thread.
            while let Some((i, job)) = queue.lock().ok().and_then(|mut q| q.next()) {
                let result = work(job);
                if let Ok(mut results) = results.lock() {
                    results.push((i, result));
                }
            }
        };
        match &self.pool {
            Some(pool) if count > 1 => pool.in_place_scope(|scope| {
                for _ in 1..self.threads.min(count) {
                    scope.spawn(|_| worker());
                }
                worker();
            }),
            _ => worker(),
        }
        let mut results = results.into_inner().unwrap_or_else(|poisoned| poisoned.into_inner());
        results.sort_unstable_by_key(|(i, _)| *i);
        results.into_iter().map(|(_, result)| result).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::thread;
    use std::time::{Duration, Instant};

    #[test]
    fn results_come_back_in_the_jobs_order_from_every_thread_count() {
        for threads in [1, 2, 3, 8] {
            let workers = Workers::new(threads);
            assert_eq!(workers.threads(), threads);
            let jobs: Vec<u64> = (0..100).collect();
            let results = workers.run(jobs, |j| j * j);
            assert_eq!(results, (0..100).map(|j| j * j).collect::<Vec<_>>(), "{threads} threads");
            assert!(workers.run(Vec::<u8>::new(), |j| j).is_empty());
        }
    }

    /// Two jobs that each wait for the other to start run on two threads at once; over several passes the one
    /// that is not the caller is always the same thread: the pool's, not one started for the pass.
    #[test]
    fn the_same_threads_run_every_pass() {
        let workers = Workers::new(2);
        let caller = thread::current().id();
        let mut helpers = HashSet::new();
        for _ in 0..5 {
            let started = AtomicUsize::new(0);
            let ids = workers.run(vec![(), ()], |()| {
                started.fetch_add(1, Ordering::SeqCst);
                let deadline = Instant::now() + Duration::from_secs(10);
                while started.load(Ordering::SeqCst) < 2 && Instant::now() < deadline {
                    thread::yield_now();
                }
                thread::current().id()
            });
            assert_ne!(ids[0], ids[1], "the two jobs ran one after the other");
            helpers.extend(ids.into_iter().filter(|&id| id != caller));
        }
        assert_eq!(helpers.len(), 1, "{helpers:?}");
    }

    #[test]
    fn a_panicking_job_panics_the_caller() {
        let workers = Workers::new(2);
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            workers.run((0..8).collect(), |j: i32| assert!(j != 5, "job 5"))
        }));
        assert!(outcome.is_err());
        // The pool still works after it.
        assert_eq!(workers.run(vec![1, 2], |j: i32| j + 1), vec![2, 3]);
    }
}
