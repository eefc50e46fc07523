//! Planet builds off the async runtime: a fixed pool of worker threads fed by a queue with a
//! bounded number of waiting jobs.
//!
//! A job is admitted while `running + waiting < workers + max_queue`; a caller first reserves a
//! [`Slot`] (so it can refuse with 429 before doing any work) and then submits the job into it.
//! Dropping an unused slot gives the place back.

use std::collections::HashMap;
use std::net::IpAddr;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::{Arc, Mutex};

type Job = Box<dyn FnOnce() + Send + 'static>;

/// The worker pool.
pub struct Pool {
    tx: Mutex<Sender<Job>>,
    admitted: Arc<AtomicUsize>,
    capacity: usize,
}

/// A reserved place in the pool.
pub struct Slot {
    pool: Arc<Pool>,
    used: bool,
}

impl Pool {
    /// Starts `workers` threads (at least one) that accept up to `max_queue` waiting jobs.
    pub fn new(workers: usize, max_queue: usize) -> Arc<Pool> {
        let (tx, rx) = channel::<Job>();
        let rx = Arc::new(Mutex::new(rx));
        let workers = workers.max(1);
        for i in 0..workers {
            let rx = Arc::clone(&rx);
            std::thread::Builder::new()
                .name(format!("planet-build-{i}"))
                .spawn(move || work(&rx))
                .expect("spawn build worker");
        }
        Arc::new(Pool { tx: Mutex::new(tx), admitted: Arc::new(AtomicUsize::new(0)), capacity: workers + max_queue })
    }

    /// A place for one job, or None when the queue is full.
    pub fn reserve(self: &Arc<Self>) -> Option<Slot> {
        let mut now = self.admitted.load(Ordering::SeqCst);
        loop {
            if now >= self.capacity {
                return None;
            }
            match self.admitted.compare_exchange(now, now + 1, Ordering::SeqCst, Ordering::SeqCst) {
                Ok(_) => return Some(Slot { pool: Arc::clone(self), used: false }),
                Err(actual) => now = actual,
            }
        }
    }

    /// Submits a job whatever the queue holds (the built-in planet at start).
    pub fn submit_unbounded(self: &Arc<Self>, job: impl FnOnce() + Send + 'static) {
        self.admitted.fetch_add(1, Ordering::SeqCst);
        Slot { pool: Arc::clone(self), used: false }.submit(job);
    }

    /// Jobs running or waiting.
    pub fn load(&self) -> usize {
        self.admitted.load(Ordering::SeqCst)
    }

    fn send(&self, job: Job) {
        // The receiver lives as long as the worker threads, which never exit.
        let _ = self.tx.lock().expect("pool lock").send(job);
    }
}

impl Slot {
    /// Hands the job to the workers; its place is given back when it has run.
    pub fn submit(mut self, job: impl FnOnce() + Send + 'static) {
        self.used = true;
        let admitted = Arc::clone(&self.pool.admitted);
        self.pool.send(Box::new(move || {
            struct Release(Arc<AtomicUsize>);
            impl Drop for Release {
                fn drop(&mut self) {
                    self.0.fetch_sub(1, Ordering::SeqCst);
                }
            }
            let _release = Release(admitted);
            job();
        }));
    }
}

impl Drop for Slot {
    fn drop(&mut self) {
        if !self.used {
            self.pool.admitted.fetch_sub(1, Ordering::SeqCst);
        }
    }
}

/// Builds queued or running per client address, at most `limit` each (0: no limit), so that
/// one client cannot fill the queue that every client shares.
pub struct PerClient {
    limit: usize,
    counts: Mutex<HashMap<IpAddr, usize>>,
}

/// One client's place, held by its build until the build has run.
pub struct ClientTicket {
    owner: Arc<PerClient>,
    ip: IpAddr,
}

impl PerClient {
    pub fn new(limit: usize) -> Arc<PerClient> {
        Arc::new(PerClient { limit, counts: Mutex::new(HashMap::new()) })
    }

    /// A place for one more build of `ip`'s, or None when it has `limit` already.
    pub fn take(self: &Arc<Self>, ip: IpAddr) -> Option<ClientTicket> {
        let mut counts = self.counts.lock().expect("clients lock");
        let n = counts.entry(ip).or_insert(0);
        if self.limit > 0 && *n >= self.limit {
            return None;
        }
        *n += 1;
        Some(ClientTicket { owner: Arc::clone(self), ip })
    }

    /// Builds of `ip`'s queued or running.
    pub fn held(&self, ip: IpAddr) -> usize {
        self.counts.lock().expect("clients lock").get(&ip).copied().unwrap_or(0)
    }
}

impl Drop for ClientTicket {
    fn drop(&mut self) {
        let mut counts = self.owner.counts.lock().expect("clients lock");
        if let Some(n) = counts.get_mut(&self.ip) {
            *n -= 1;
            if *n == 0 {
                counts.remove(&self.ip);
            }
        }
    }
}

fn work(rx: &Mutex<Receiver<Job>>) {
    loop {
        let job = match rx.lock().expect("queue lock").recv() {
            Ok(job) => job,
            Err(_) => return,
        };
        // A panicking build is reported by the job itself; keep the worker alive regardless.
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(job));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::mpsc::sync_channel;

    #[test]
    fn admits_workers_plus_queue_then_refuses() {
        let pool = Pool::new(1, 1);
        let (go_tx, go_rx) = sync_channel::<()>(0);
        let go_rx = Arc::new(Mutex::new(go_rx));
        for _ in 0..2 {
            let rx = Arc::clone(&go_rx);
            pool.reserve().expect("room").submit(move || {
                let _ = rx.lock().unwrap().recv();
            });
        }
        assert!(pool.reserve().is_none());
        go_tx.send(()).unwrap();
        go_tx.send(()).unwrap();
        for _ in 0..200 {
            if pool.load() == 0 {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        assert_eq!(pool.load(), 0);
        drop(pool.reserve().expect("room again"));
        assert_eq!(pool.load(), 0);
    }

    #[test]
    fn each_client_holds_at_most_its_share() {
        let clients = PerClient::new(2);
        let (a, b): (IpAddr, IpAddr) = ("10.0.0.1".parse().unwrap(), "10.0.0.2".parse().unwrap());
        let first = clients.take(a).unwrap();
        let _second = clients.take(a).unwrap();
        assert!(clients.take(a).is_none());
        let _other = clients.take(b).expect("another client has its own share");
        drop(first);
        assert_eq!(clients.held(a), 1);
        assert!(clients.take(a).is_some());
        assert!(PerClient::new(0).take(a).is_some(), "0: no limit");
    }
}
