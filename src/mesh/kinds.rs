//! Types of faces, edges and vertices (paper §3.2).

/// A face belongs to the sea or to a continent.
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum FaceKind {
    Sea = 0,
    Land = 1,
}

/// Edges are sea, coast or continent from their two faces; continent edges may be rivers.
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum EdgeKind {
    Sea = 0,
    Coast = 1,
    Continent = 2,
    River = 3,
}

impl EdgeKind {
    /// The kind an edge between faces of kinds `a` and `b` takes before rivers are assigned.
    pub fn between(a: FaceKind, b: FaceKind) -> EdgeKind {
        match (a, b) {
            (FaceKind::Sea, FaceKind::Sea) => EdgeKind::Sea,
            (FaceKind::Land, FaceKind::Land) => EdgeKind::Continent,
            _ => EdgeKind::Coast,
        }
    }
    pub fn flag(self) -> VertexFlags {
        VertexFlags(1 << self as u8)
    }
}

/// A vertex has all the types of its incident edges (§3.2), as bits, and a mark for vertices
/// made by adaption.
#[repr(transparent)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, bytemuck::NoUninit, bytemuck::AnyBitPattern)]
pub struct VertexFlags(pub u8);

impl VertexFlags {
    pub const SEA: VertexFlags = VertexFlags(1);
    pub const COAST: VertexFlags = VertexFlags(2);
    pub const CONTINENT: VertexFlags = VertexFlags(4);
    pub const RIVER: VertexFlags = VertexFlags(8);
    /// A coast vertex where a river reaches the sea.
    pub const MOUTH: VertexFlags = VertexFlags(16);
    /// A land vertex placed to separate rivers (eq. 5); never becomes a river.
    pub const MOUNTAIN: VertexFlags = VertexFlags(32);
    /// Made by a split, so a collapse may remove it; base-mesh vertices never collapse.
    pub const REFINED: VertexFlags = VertexFlags(64);
    /// On a lake's bed, under its water: splits between two such vertices stay under it (no
    /// island the map does not have). A river vertex so flagged with no lower river neighbour
    /// is the pit of a closed basin, where its rivers end (in a terminal lake or a dry pan).
    pub const LAKE: VertexFlags = VertexFlags(128);

    pub const fn empty() -> VertexFlags {
        VertexFlags(0)
    }
    #[inline]
    pub fn contains(self, other: VertexFlags) -> bool {
        self.0 & other.0 == other.0
    }
    #[inline]
    pub fn intersects(self, other: VertexFlags) -> bool {
        self.0 & other.0 != 0
    }
    #[inline]
    pub fn insert(&mut self, other: VertexFlags) {
        self.0 |= other.0;
    }
    #[inline]
    pub fn remove(&mut self, other: VertexFlags) {
        self.0 &= !other.0;
    }
    /// Only sea edges meet here.
    pub fn is_pure_sea(self) -> bool {
        self.0 & 0b1111 == Self::SEA.0
    }
    /// On land: touches a continent or river edge and no sea edge.
    pub fn is_inland(self) -> bool {
        !self.intersects(VertexFlags(Self::SEA.0 | Self::COAST.0))
    }
}

impl std::ops::BitOr for VertexFlags {
    type Output = VertexFlags;
    fn bitor(self, rhs: VertexFlags) -> VertexFlags {
        VertexFlags(self.0 | rhs.0)
    }
}
