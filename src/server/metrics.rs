//! Prometheus metrics in the text exposition format: requests by route, method and status, a
//! latency histogram by route, build counters and cache hits and misses.

use axum::body::Body;
use axum::extract::MatchedPath;
use axum::http::Request;
use axum::middleware::Next;
use axum::response::Response;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::Instant;

/// Upper bounds of the latency histogram buckets, seconds.
const BUCKETS: [f64; 14] = [0.001, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 30.0, 120.0];

#[derive(Default)]
struct Histogram {
    counts: [u64; BUCKETS.len()],
    sum: f64,
    count: u64,
}

/// The counters.
#[derive(Default)]
pub struct Metrics {
    requests: Mutex<BTreeMap<(String, String, u16), u64>>,
    latency: Mutex<BTreeMap<String, Histogram>>,
    builds_started: AtomicU64,
    builds_finished: AtomicU64,
    builds_failed: AtomicU64,
    cache: Mutex<BTreeMap<(&'static str, bool), u64>>,
}

impl Metrics {
    pub fn build_started(&self) {
        self.builds_started.fetch_add(1, Ordering::Relaxed);
    }
    pub fn build_finished(&self) {
        self.builds_finished.fetch_add(1, Ordering::Relaxed);
    }
    pub fn build_failed(&self) {
        self.builds_failed.fetch_add(1, Ordering::Relaxed);
    }
    /// A lookup in cache `which` ("planet" or "response") found its value.
    pub fn cache_hit(&self, which: &'static str) {
        *self.cache.lock().expect("metrics lock").entry((which, true)).or_default() += 1;
    }
    /// A lookup in cache `which` had to build or render the value.
    pub fn cache_miss(&self, which: &'static str) {
        *self.cache.lock().expect("metrics lock").entry((which, false)).or_default() += 1;
    }

    fn observe(&self, route: &str, method: &str, status: u16, secs: f64) {
        *self.requests.lock().expect("metrics lock").entry((route.into(), method.into(), status)).or_default() += 1;
        let mut lat = self.latency.lock().expect("metrics lock");
        let h = lat.entry(route.to_string()).or_default();
        for (i, le) in BUCKETS.iter().enumerate() {
            if secs <= *le {
                h.counts[i] += 1;
            }
        }
        h.sum += secs;
        h.count += 1;
    }

    /// The exposition text; `gauges` are extra (name, help, value) lines.
    pub fn render(&self, gauges: &[(&str, &str, f64)]) -> String {
        let mut out = String::new();
        out.push_str("# HELP riverworld_http_requests_total HTTP requests by route, method and status.\n");
        out.push_str("# TYPE riverworld_http_requests_total counter\n");
        for ((route, method, status), n) in self.requests.lock().expect("metrics lock").iter() {
            let _ = writeln!(
                out,
                "riverworld_http_requests_total{{route=\"{route}\",method=\"{method}\",status=\"{status}\"}} {n}"
            );
        }
        out.push_str("# HELP riverworld_http_request_duration_seconds HTTP request latency by route.\n");
        out.push_str("# TYPE riverworld_http_request_duration_seconds histogram\n");
        for (route, h) in self.latency.lock().expect("metrics lock").iter() {
            let name = "riverworld_http_request_duration_seconds";
            for (le, n) in BUCKETS.iter().zip(h.counts) {
                let _ = writeln!(out, "{name}_bucket{{route=\"{route}\",le=\"{le}\"}} {n}");
            }
            let _ = writeln!(out, "{name}_bucket{{route=\"{route}\",le=\"+Inf\"}} {}", h.count);
            let _ = writeln!(out, "{name}_sum{{route=\"{route}\"}} {}", h.sum);
            let _ = writeln!(out, "{name}_count{{route=\"{route}\"}} {}", h.count);
        }
        for (name, help, v) in [
            ("riverworld_builds_started_total", "Planet builds started.", &self.builds_started),
            ("riverworld_builds_finished_total", "Planet builds finished.", &self.builds_finished),
            ("riverworld_builds_failed_total", "Planet builds failed.", &self.builds_failed),
        ] {
            let _ = writeln!(out, "# HELP {name} {help}\n# TYPE {name} counter\n{name} {}", v.load(Ordering::Relaxed));
        }
        let cache = self.cache.lock().expect("metrics lock");
        for (hit, name, help) in [
            (true, "riverworld_cache_hits_total", "Cache lookups that found their value."),
            (false, "riverworld_cache_misses_total", "Cache lookups that had to build or render."),
        ] {
            let _ = writeln!(out, "# HELP {name} {help}\n# TYPE {name} counter");
            for which in ["planet", "response"] {
                let n = cache.get(&(which, hit)).copied().unwrap_or(0);
                let _ = writeln!(out, "{name}{{cache=\"{which}\"}} {n}");
            }
        }
        for (name, help, v) in gauges {
            let _ = writeln!(out, "# HELP {name} {help}\n# TYPE {name} gauge\n{name} {v}");
        }
        out
    }
}

/// A request method as a label from a fixed set: the standard methods, `other` for the rest, so
/// that clients cannot grow the metrics (or the logs) with methods of their own.
pub fn method_label(m: &axum::http::Method) -> &'static str {
    const KNOWN: [&str; 9] = ["GET", "HEAD", "POST", "PUT", "DELETE", "OPTIONS", "PATCH", "TRACE", "CONNECT"];
    KNOWN.iter().find(|&&k| k == m.as_str()).copied().unwrap_or("other")
}

impl Metrics {
    /// Runs a request (the rest of the middleware stack) and counts it under its route pattern
    /// (`unmatched` for none) and method label ([`method_label`]).
    pub async fn track(&self, req: Request<Body>, next: Next) -> Response {
        let route = req.extensions().get::<MatchedPath>().map(|p| p.as_str().to_string());
        let route = route.unwrap_or_else(|| "unmatched".to_string());
        let method = method_label(req.method()).to_string();
        let start = Instant::now();
        let res = next.run(req).await;
        self.observe(&route, &method, res.status().as_u16(), start.elapsed().as_secs_f64());
        res
    }
}
