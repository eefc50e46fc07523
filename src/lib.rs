//! riverworld: procedural planets with river networks after Derzapf et al., *River Networks for
//! Instant Procedural Planets* (2011). Data flows one way:
//! `maps -> planet -> mesh -> adapt -> export / render -> server`.

pub mod adapt;
pub mod export;
pub mod geo;
pub mod input;
pub mod maps;
pub mod mesh;
pub mod params;
pub mod planet;
pub mod query;
#[cfg(feature = "service")]
pub mod render;
pub mod rng;
#[cfg(feature = "service")]
pub mod server;
