//! riverworld: procedural planets with river networks after Derzapf et al., *River Networks for
//! Instant Procedural Planets* (2011). Data flows one way:
//! `maps -> build -> mesh -> adapt -> export / render -> server`.

pub mod adapt;
#[cfg(feature = "service")]
pub mod bench;
pub mod bench_adapt;
#[cfg(feature = "service")]
pub mod bench_backends;
#[cfg(feature = "service")]
pub mod bench_render;
pub mod build;
pub mod export;
pub mod generate;
pub mod geo;
pub mod maps;
pub mod mesh;
pub mod params;
pub mod query;
#[cfg(feature = "service")]
pub mod render;
pub mod rng;
#[cfg(feature = "service")]
pub mod server;
