//! Admission of heavy work done inside a request (rendering a view that is not cached, ...): a
//! fixed number of permits, a memory budget that each render draws its working memory from
//! (known before it starts: faces of the view, pixels of the image), and a small bounded wait
//! queue. A request that finds no permit or not enough of the budget, and the queue full, is
//! refused at once with 429 `busy` and `Retry-After`, instead of queueing without bound while
//! memory and latency grow. Work larger than the whole budget runs alone.

use super::error::ApiError;
use axum::http::StatusCode;
use std::sync::atomic::{AtomicUsize, Ordering};
use tokio::sync::{Semaphore, SemaphorePermit};

/// Permits for heavy work and its memory budget, with a bounded number of waiters.
pub struct HeavyLimit {
    permits: Semaphore,
    total: usize,
    /// The memory budget in MiB.
    memory: Semaphore,
    memory_mib: u32,
    queue: usize,
    waiting: AtomicUsize,
}

/// What an admitted request holds until its work is done.
#[derive(Debug)]
pub struct Admitted<'a> {
    _permit: SemaphorePermit<'a>,
    _memory: SemaphorePermit<'a>,
}

/// 429 `busy` with `Retry-After: 1`.
pub fn busy() -> ApiError {
    ApiError::new(StatusCode::TOO_MANY_REQUESTS, "busy", "the server is busy rendering other requests; retry later")
        .retry_after(1)
}

impl HeavyLimit {
    /// `permits` running at once (at least one) within `memory_mib` MiB of working memory
    /// (at least one), at most `queue` waiting.
    pub fn new(permits: usize, memory_mib: u32, queue: usize) -> HeavyLimit {
        let total = permits.max(1);
        let memory_mib = memory_mib.max(1);
        HeavyLimit {
            permits: Semaphore::new(total),
            total,
            memory: Semaphore::new(memory_mib as usize),
            memory_mib,
            queue,
            waiting: AtomicUsize::new(0),
        }
    }

    /// MiB of the budget that `bytes` of working memory draw: at least one, at most all.
    fn share(&self, bytes: u64) -> u32 {
        bytes.div_ceil(1 << 20).clamp(1, u64::from(self.memory_mib)) as u32
    }

    /// A permit and `bytes` of the memory budget now, or after waiting in the queue if it has
    /// room; else 429 `busy`. Dropping the future leaves the queue.
    pub async fn admit(&self, bytes: u64) -> Result<Admitted<'_>, ApiError> {
        let mib = self.share(bytes);
        if let (Ok(permit), Ok(memory)) = (self.permits.try_acquire(), self.memory.try_acquire_many(mib)) {
            return Ok(Admitted { _permit: permit, _memory: memory });
        }
        let mut now = self.waiting.load(Ordering::SeqCst);
        loop {
            if now >= self.queue {
                return Err(busy());
            }
            match self.waiting.compare_exchange(now, now + 1, Ordering::SeqCst, Ordering::SeqCst) {
                Ok(_) => break,
                Err(actual) => now = actual,
            }
        }
        struct Leave<'a>(&'a AtomicUsize);
        impl Drop for Leave<'_> {
            fn drop(&mut self) {
                self.0.fetch_sub(1, Ordering::SeqCst);
            }
        }
        let _leave = Leave(&self.waiting);
        let closed = |_| ApiError::internal("shutting down");
        let permit = self.permits.acquire().await.map_err(closed)?;
        let memory = self.memory.acquire_many(mib).await.map_err(closed)?;
        Ok(Admitted { _permit: permit, _memory: memory })
    }

    /// A permit and `bytes` of the memory budget, waiting as long as it takes, outside the
    /// bounded queue: for work bounded by a queue of its own (planet builds).
    pub async fn admit_unqueued(&self, bytes: u64) -> Result<Admitted<'_>, ApiError> {
        let closed = |_| ApiError::internal("shutting down");
        let permit = self.permits.acquire().await.map_err(closed)?;
        let memory = self.memory.acquire_many(self.share(bytes)).await.map_err(closed)?;
        Ok(Admitted { _permit: permit, _memory: memory })
    }

    /// MiB of the memory budget held now.
    pub fn memory_held_mib(&self) -> usize {
        self.memory_mib as usize - self.memory.available_permits()
    }

    /// Permits held now.
    pub fn running(&self) -> usize {
        self.total - self.permits.available_permits()
    }

    /// Requests waiting for a permit now.
    pub fn waiting(&self) -> usize {
        self.waiting.load(Ordering::SeqCst)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn admits_permits_then_queue_then_refuses() {
        let limit = std::sync::Arc::new(HeavyLimit::new(1, 64, 1));
        let held = limit.admit(1).await.unwrap();
        assert_eq!((limit.running(), limit.waiting()), (1, 0));
        let l2 = std::sync::Arc::clone(&limit);
        let waiter = tokio::spawn(async move { l2.admit(1).await.map(|_| ()) });
        while limit.waiting() == 0 {
            tokio::task::yield_now().await;
        }
        let err = limit.admit(1).await.unwrap_err();
        assert_eq!((err.status.as_u16(), err.code.as_str(), err.retry_after), (429, "busy", Some(1)));
        drop(held);
        waiter.await.unwrap().unwrap();
        assert_eq!((limit.running(), limit.waiting()), (0, 0));
        // A cancelled waiter gives its place back.
        let held = limit.admit(1).await.unwrap();
        let l3 = std::sync::Arc::clone(&limit);
        let cancelled = tokio::spawn(async move { l3.admit(1).await.map(|_| ()) });
        while limit.waiting() == 0 {
            tokio::task::yield_now().await;
        }
        cancelled.abort();
        let _ = cancelled.await;
        assert_eq!(limit.waiting(), 0);
        drop(held);
    }

    #[tokio::test]
    async fn renders_share_the_memory_budget() {
        // Four permits, 100 MiB: two 40 MiB renders run together, a third waits for memory.
        let limit = std::sync::Arc::new(HeavyLimit::new(4, 100, 4));
        let a = limit.admit(40 << 20).await.unwrap();
        let _b = limit.admit(40 << 20).await.unwrap();
        assert_eq!(limit.memory_held_mib(), 80);
        let l2 = std::sync::Arc::clone(&limit);
        let third = tokio::spawn(async move { l2.admit(40 << 20).await.map(|_| ()) });
        while limit.waiting() == 0 {
            tokio::task::yield_now().await;
        }
        for _ in 0..100 {
            tokio::task::yield_now().await;
        }
        assert!(!third.is_finished(), "40 MiB more than the 20 left");
        drop(a);
        third.await.unwrap().unwrap();
        // Work over the whole budget runs alone; tiny work draws one MiB.
        drop(_b);
        let huge = limit.admit(1 << 40).await.unwrap();
        assert_eq!(limit.memory_held_mib(), 100);
        drop(huge);
        let _tiny = limit.admit(1).await.unwrap();
        assert_eq!(limit.memory_held_mib(), 1);
    }
}
