//! Admission of heavy work done inside a request (rendering a view that is not cached, ...): a
//! fixed number of permits plus a small bounded wait queue. A request that finds every permit
//! taken and the queue full is refused at once with 429 `busy` and `Retry-After`, instead of
//! queueing without bound while memory and latency grow.

use super::error::ApiError;
use axum::http::StatusCode;
use std::sync::atomic::{AtomicUsize, Ordering};
use tokio::sync::{Semaphore, SemaphorePermit};

/// Permits for heavy work, with a bounded number of waiters.
pub struct HeavyLimit {
    permits: Semaphore,
    total: usize,
    queue: usize,
    waiting: AtomicUsize,
}

/// 429 `busy` with `Retry-After: 1`.
pub fn busy() -> ApiError {
    ApiError::new(StatusCode::TOO_MANY_REQUESTS, "busy", "the server is busy rendering other requests; retry later")
        .retry_after(1)
}

impl HeavyLimit {
    /// `permits` running at once (at least one), at most `queue` waiting for one.
    pub fn new(permits: usize, queue: usize) -> HeavyLimit {
        let total = permits.max(1);
        HeavyLimit { permits: Semaphore::new(total), total, queue, waiting: AtomicUsize::new(0) }
    }

    /// A permit now, or after waiting in the queue if it has room; else 429 `busy`. Dropping the
    /// future leaves the queue.
    pub async fn admit(&self) -> Result<SemaphorePermit<'_>, ApiError> {
        if let Ok(permit) = self.permits.try_acquire() {
            return Ok(permit);
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
        self.permits.acquire().await.map_err(|_| ApiError::internal("shutting down"))
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
        let limit = std::sync::Arc::new(HeavyLimit::new(1, 1));
        let held = limit.admit().await.unwrap();
        assert_eq!((limit.running(), limit.waiting()), (1, 0));
        let l2 = std::sync::Arc::clone(&limit);
        let waiter = tokio::spawn(async move { l2.admit().await.map(|_| ()) });
        while limit.waiting() == 0 {
            tokio::task::yield_now().await;
        }
        let err = limit.admit().await.unwrap_err();
        assert_eq!((err.status.as_u16(), err.code.as_str(), err.retry_after), (429, "busy", Some(1)));
        drop(held);
        waiter.await.unwrap().unwrap();
        assert_eq!((limit.running(), limit.waiting()), (0, 0));
        // A cancelled waiter gives its place back.
        let held = limit.admit().await.unwrap();
        let l3 = std::sync::Arc::clone(&limit);
        let cancelled = tokio::spawn(async move { l3.admit().await.map(|_| ()) });
        while limit.waiting() == 0 {
            tokio::task::yield_now().await;
        }
        cancelled.abort();
        let _ = cancelled.await;
        assert_eq!(limit.waiting(), 0);
        drop(held);
    }
}
