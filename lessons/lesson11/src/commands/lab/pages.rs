//! The pages that use the lab, each with at most one render: a new render
//! of a page stops the one it replaces. At most [`MAX_PAGES`] pages are
//! kept (the least recently used one is dropped, its render stopped), so
//! memory stays bounded whatever the clients do; and a page that stopped
//! asking (its tab was closed) has its render stopped after [`IDLE`].

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant};

use super::job::{Job, JobSpec};

/// The most pages with a render of their own (four browser tabs).
pub const MAX_PAGES: usize = 4;

/// A page asks for its render's progress at least every 2 s while it is
/// open; after this long without a word its render is stopped.
pub const IDLE: Duration = Duration::from_secs(10);

struct Page {
    job: Option<Arc<Job>>,
    /// The job the current one replaced: the page reads how fast it stopped.
    previous: Option<Arc<Job>>,
    used: Instant,
}

/// Every page's render.
#[derive(Default)]
pub struct Pages {
    pages: Mutex<HashMap<String, Page>>,
    next_id: AtomicU64,
    /// Renders (their jobs' threads) running in the whole lab.
    pub running: Arc<AtomicUsize>,
}

impl Pages {
    fn lock(&self) -> MutexGuard<'_, HashMap<String, Page>> {
        self.pages.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Stops the page's render and starts `spec` in its place.
    pub fn start(&self, page: &str, spec: JobSpec) -> Result<Arc<Job>, String> {
        let mut pages = self.lock();
        if !pages.contains_key(page) && pages.len() >= MAX_PAGES {
            let oldest = pages
                .iter()
                .min_by_key(|(_, p)| p.used)
                .map(|(k, _)| k.clone());
            if let Some(p) = oldest.and_then(|k| pages.remove(&k)) {
                p.job.iter().for_each(|j| j.cancel());
            }
        }
        let entry = pages.entry(page.to_string()).or_insert(Page {
            job: None,
            previous: None,
            used: Instant::now(),
        });
        entry.used = Instant::now();
        if let Some(old) = entry.job.take() {
            old.cancel();
            entry.previous = Some(old);
        }
        let id = self.next_id.fetch_add(1, Ordering::Relaxed) + 1;
        let job = Job::start(id, spec, &self.running)?;
        entry.job = Some(job.clone());
        Ok(job)
    }

    /// The page's render, if it has one.
    pub fn job(&self, page: &str) -> Option<Arc<Job>> {
        let mut pages = self.lock();
        let p = pages.get_mut(page)?;
        p.used = Instant::now();
        p.job.clone()
    }

    /// The render that the page's current one replaced.
    pub fn previous(&self, page: &str) -> Option<Arc<Job>> {
        self.lock().get(page)?.previous.clone()
    }

    /// Stops the page's render (the picture so far stays).
    pub fn stop(&self, page: &str) {
        if let Some(job) = self.job(page) {
            job.cancel();
        }
    }

    /// Stops the renders of pages not heard from for `idle`.
    pub fn stop_idle(&self, idle: Duration) {
        for p in self.lock().values() {
            if p.used.elapsed() > idle {
                p.job.iter().for_each(|j| j.cancel());
            }
        }
    }

    /// Stops every render (the lab is closing).
    pub fn stop_all(&self) {
        for p in self.lock().values() {
            p.job.iter().for_each(|j| j.cancel());
        }
    }
}
