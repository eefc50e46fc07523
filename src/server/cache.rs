//! A least-recently-used cache bounded in bytes, shared by built planets and rendered responses.
//!
//! Every entry carries its weight in bytes; inserting evicts the least recently used entries
//! until the total fits the budget, but never the entry just inserted, so a single planet larger
//! than the whole budget can still be served (it is the first to go when anything else arrives).
//! Pinned keys (the built-in planet) are never evicted; their bytes count against the budget.

use std::collections::HashMap;
use std::sync::Mutex;

struct Slot<V> {
    value: V,
    bytes: usize,
    used: u64,
}

struct Inner<V> {
    map: HashMap<String, Slot<V>>,
    total: usize,
    tick: u64,
    /// Keys never evicted (still removed by [`ByteLru::remove_prefix`]).
    pinned: Vec<String>,
}

/// Byte-bounded LRU map from string keys to cheaply clonable values.
pub struct ByteLru<V> {
    budget: usize,
    inner: Mutex<Inner<V>>,
}

impl<V: Clone> ByteLru<V> {
    pub fn new(budget: usize) -> ByteLru<V> {
        ByteLru { budget, inner: Mutex::new(Inner { map: HashMap::new(), total: 0, tick: 0, pinned: Vec::new() }) }
    }

    /// Never evicts `key` (whether cached yet or not).
    pub fn pin(&self, key: &str) {
        let mut inner = self.inner.lock().expect("cache lock");
        if !inner.pinned.iter().any(|k| k == key) {
            inner.pinned.push(key.to_string());
        }
    }

    /// The value under `key`, marking it most recently used.
    pub fn get(&self, key: &str) -> Option<V> {
        let mut inner = self.inner.lock().expect("cache lock");
        inner.tick += 1;
        let tick = inner.tick;
        inner.map.get_mut(key).map(|s| {
            s.used = tick;
            s.value.clone()
        })
    }

    /// Whether `key` is cached, without touching its recency.
    pub fn contains(&self, key: &str) -> bool {
        self.inner.lock().expect("cache lock").map.contains_key(key)
    }

    /// Inserts (or replaces) `key`, then evicts least recently used entries over the budget.
    pub fn insert(&self, key: String, value: V, bytes: usize) {
        let mut inner = self.inner.lock().expect("cache lock");
        inner.tick += 1;
        let used = inner.tick;
        if let Some(old) = inner.map.insert(key.clone(), Slot { value, bytes, used }) {
            inner.total -= old.bytes;
        }
        inner.total += bytes;
        while inner.total > self.budget {
            let oldest = inner
                .map
                .iter()
                .filter(|(k, _)| **k != key && !inner.pinned.contains(k))
                .min_by_key(|(_, s)| s.used)
                .map(|(k, _)| k.clone());
            let Some(oldest) = oldest else { break };
            let gone = inner.map.remove(&oldest).expect("present");
            inner.total -= gone.bytes;
        }
    }

    /// Removes every entry whose key starts with `prefix`.
    pub fn remove_prefix(&self, prefix: &str) {
        let mut inner = self.inner.lock().expect("cache lock");
        let keys: Vec<String> = inner.map.keys().filter(|k| k.starts_with(prefix)).cloned().collect();
        for k in keys {
            let gone = inner.map.remove(&k).expect("present");
            inner.total -= gone.bytes;
        }
    }

    /// Bytes held now.
    pub fn bytes(&self) -> usize {
        self.inner.lock().expect("cache lock").total
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn evicts_least_recently_used_first_and_keeps_the_newest() {
        let c = ByteLru::new(10);
        c.insert("a".into(), 1, 4);
        c.insert("b".into(), 2, 4);
        assert_eq!(c.get("a"), Some(1));
        c.insert("c".into(), 3, 4);
        assert_eq!((c.get("a"), c.get("b"), c.get("c")), (Some(1), None, Some(3)));
        c.insert("big".into(), 4, 100);
        assert_eq!((c.get("a"), c.get("c"), c.get("big")), (None, None, Some(4)));
        assert_eq!(c.bytes(), 100);
        c.insert("p/1".into(), 5, 1);
        c.remove_prefix("p/");
        assert!(!c.contains("p/1"));
    }

    #[test]
    fn pinned_entries_stay() {
        let c: ByteLru<u32> = ByteLru::new(100);
        c.pin("earth");
        c.insert("earth".into(), 1, 60);
        for i in 0..10 {
            c.insert(format!("upload{i}"), i, 60);
        }
        assert!(c.contains("earth"), "the pinned entry survives newer, larger ones");
        assert!(c.contains("upload9") && !c.contains("upload8"));
        assert_eq!(c.bytes(), 120);
        c.remove_prefix("earth");
        assert!(!c.contains("earth"));
    }
}
