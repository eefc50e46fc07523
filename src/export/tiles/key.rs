//! Tile addresses: a root cell (one of the octahedron's eight faces) and one quadrant digit per
//! level below it, written as digits — `"3"` is root cell 3, `"3021"` its level-3 descendant
//! through quadrants 0, 2 and 1 — and the file names built from them (`3021.glb`, `3021.json`).
//!
//! A quadrant is two bisections: digit `q` takes child `q >> 1` of the cell, then child `q & 1`
//! of that (see `tree.rs` for the child order).

use std::fmt;

/// Deepest level a key can name (two bits per level in a `u64`).
pub const KEY_MAX_LEVEL: u8 = 30;

/// One tile: root cell, level and quadrant path (two bits per level, the first quadrant in the
/// highest used bits).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct TileKey {
    pub root: u8,
    pub level: u8,
    pub path: u64,
}

impl TileKey {
    /// Root cell `root` (0..8) at level 0.
    pub fn root(root: u8) -> TileKey {
        assert!(root < 8, "root cell out of range");
        TileKey { root, level: 0, path: 0 }
    }

    /// The child in quadrant `q` (0..4).
    pub fn child(self, q: u8) -> TileKey {
        assert!(q < 4 && self.level < KEY_MAX_LEVEL, "child out of range");
        TileKey { root: self.root, level: self.level + 1, path: (self.path << 2) | u64::from(q) }
    }

    pub fn children(self) -> [TileKey; 4] {
        [0, 1, 2, 3].map(|q| self.child(q))
    }

    /// The parent, or `None` at level 0.
    pub fn parent(self) -> Option<TileKey> {
        (self.level > 0).then(|| TileKey { root: self.root, level: self.level - 1, path: self.path >> 2 })
    }

    /// Quadrant digits from the top down.
    pub fn quadrants(self) -> impl Iterator<Item = u8> {
        (0..self.level).rev().map(move |i| ((self.path >> (2 * u32::from(i))) & 3) as u8)
    }

    /// Parses a key written by [`fmt::Display`]: a root digit `0`-`7`, then up to
    /// `max_level` quadrant digits `0`-`3`.
    pub fn parse(s: &str, max_level: u8) -> Result<TileKey, KeyError> {
        let bytes = s.as_bytes();
        let (&first, rest) = bytes.split_first().ok_or(KeyError::Malformed)?;
        if !(b'0'..=b'7').contains(&first) || !rest.iter().all(|b| (b'0'..=b'3').contains(b)) {
            return Err(KeyError::Malformed);
        }
        if rest.len() > usize::from(max_level.min(KEY_MAX_LEVEL)) {
            return Err(KeyError::TooDeep);
        }
        Ok(rest.iter().fold(TileKey::root(first - b'0'), |k, b| k.child(b - b'0')))
    }
}

impl fmt::Display for TileKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.root)?;
        for q in self.quadrants() {
            write!(f, "{q}")?;
        }
        Ok(())
    }
}

/// Why a tile key was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum KeyError {
    #[error("a tile key is a root digit 0-7 followed by quadrant digits 0-3")]
    Malformed,
    #[error("the tile is deeper than the planet's deepest level")]
    TooDeep,
}

/// What a tile file name asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TileFile {
    /// `{key}.glb`: the tile's mesh.
    Content(TileKey),
    /// `{key}.json`: the tileset of the subtree below a subtree root.
    Subtree(TileKey),
}

impl TileFile {
    /// Parses `{key}.glb` or `{key}.json`.
    pub fn parse(name: &str, max_level: u8) -> Result<TileFile, KeyError> {
        if let Some(key) = name.strip_suffix(".glb") {
            Ok(TileFile::Content(TileKey::parse(key, max_level)?))
        } else if let Some(key) = name.strip_suffix(".json") {
            Ok(TileFile::Subtree(TileKey::parse(key, max_level)?))
        } else {
            Err(KeyError::Malformed)
        }
    }

    pub fn key(self) -> TileKey {
        match self {
            TileFile::Content(k) | TileFile::Subtree(k) => k,
        }
    }

    /// The file name, relative to the `tiles/` directory.
    pub fn name(self) -> String {
        match self {
            TileFile::Content(k) => format!("{k}.glb"),
            TileFile::Subtree(k) => format!("{k}.json"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_round_trip_through_their_names() {
        let k = TileKey::root(3).child(0).child(2).child(1);
        assert_eq!(k.to_string(), "3021");
        assert_eq!(TileKey::parse("3021", 20), Ok(k));
        assert_eq!(k.parent().unwrap().to_string(), "302");
        assert_eq!(k.quadrants().collect::<Vec<_>>(), vec![0, 2, 1]);
        assert_eq!(TileFile::parse("3021.json", 20), Ok(TileFile::Subtree(k)));
        assert_eq!(TileFile::Content(k).name(), "3021.glb");
    }

    #[test]
    fn bad_keys_are_refused() {
        for bad in ["", "8", "34", "0a", "../0", "0/1", "-1", " 0", "0.glb"] {
            assert_eq!(TileKey::parse(bad, 20), Err(KeyError::Malformed), "{bad:?}");
        }
        assert_eq!(TileKey::parse("0123", 2), Err(KeyError::TooDeep));
        assert_eq!(TileKey::parse(&"0".repeat(40), 60), Err(KeyError::TooDeep));
        assert_eq!(TileFile::parse("01.png", 20), Err(KeyError::Malformed));
    }
}
