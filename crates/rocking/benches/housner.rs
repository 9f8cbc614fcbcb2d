//! Speed of the engine on the case of `bench/scipy_peer.py`: a 0.5 m × 2 m
//! block on a fixed base, 20 s of 0.5 g at 2 Hz, rtol 1e-8 (atol 1e-10), and the
//! same block on a sliding building.
//!
//! `cargo bench -p rocking --bench housner`; compare with
//! `python3 scripts/peer/scipy_peer.py 0.5 2.0 20 1e-8 0.5 2.0` (see the README).

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use rocking::{reference::solid_block, simulate, Building, GroundMotion, Harmonic, Initial, Model, NormalForce, Settings};
use std::hint::black_box;

const G: f64 = 9.81;

fn fixed_base(c: &mut Criterion) {
    let model = match Model::new(Some(solid_block(0.5, 2.0)), None, G) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    };
    let ground = match Harmonic::new(0.5 * G, 2.0, 20.0, 0.0) {
        Ok(h) => GroundMotion::Harmonic(h),
        Err(e) => panic!("{e}"),
    };
    let settings = Settings {
        duration: 20.0,
        rtol: 1e-8,
        atol: 1e-10,
    };
    c.bench_function("housner_fixed_base_20s_2hz_0.5g", |b| {
        b.iter(|| simulate(black_box(&model), black_box(&ground), Initial::default(), &settings, &mut ()).map(|s| s.max_abs_theta()))
    });
    let building = Building::new(2.0e4, 0.3, 0.25, NormalForce::Dynamic).ok();
    let model = match Model::new(Some(solid_block(0.5, 2.0)), building, G) {
        Ok(m) => m,
        Err(e) => panic!("{e}"),
    };
    c.bench_function("housner_on_sliding_building_20s_2hz_0.5g", |b| {
        b.iter(|| simulate(black_box(&model), black_box(&ground), Initial::default(), &settings, &mut ()).map(|s| s.max_abs_theta()))
    });
}

criterion_group!(benches, fixed_base);
criterion_main!(benches);
