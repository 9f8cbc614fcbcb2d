//! Speed of the response spectra: El Centro 1940 NS (1,559 samples at 0.02 s)
//! and a 3,000-sample record, each at the 100 default periods (0.02–4 s) and 5%;
//! and a set of 7 such records.
//!
//! `cargo bench -p rocking-codes --bench spectra`.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use rocking::{CsvOptions, Record};
use rocking_codes::{response_spectrum, DEFAULT_PERIODS};
use std::hint::black_box;

fn el_centro() -> Record {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/records/elcentro_1940_ns.AT2");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Record::parse(&text, None, &CsvOptions::default(), 9.81).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// A 3,000-sample record at 0.01 s: a sum of three decaying harmonics.
fn synthetic() -> Record {
    let a = (0..3000)
        .map(|k| {
            let t = k as f64 * 0.01;
            (-0.1 * t).exp() * (3.0 * t).sin() + 0.5 * (7.3 * t).sin() + 0.2 * (19.0 * t).cos()
        })
        .collect();
    Record::uniform(0.01, a).unwrap_or_else(|e| panic!("{e}"))
}

fn spectra(c: &mut Criterion) {
    let periods = DEFAULT_PERIODS.periods().unwrap_or_else(|e| panic!("{e}"));
    let elcentro = el_centro();
    let long = synthetic();
    c.bench_function("El Centro, 100 periods", |b| b.iter(|| response_spectrum(black_box(&elcentro), &periods, 5.0)));
    c.bench_function("3000 samples, 100 periods", |b| b.iter(|| response_spectrum(black_box(&long), &periods, 5.0)));
    let set: Vec<Record> = (0..7).map(|k| long.scaled(1.0 + 0.1 * k as f64)).collect();
    c.bench_function("7 records of 3000 samples, 100 periods", |b| {
        b.iter(|| set.iter().map(|r| response_spectrum(black_box(r), &periods, 5.0)).collect::<Vec<_>>())
    });
}

criterion_group!(benches, spectra);
criterion_main!(benches);
