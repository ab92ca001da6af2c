//! The golden model on a user's path: `tmc429 run --engine model` on
//! examples/scenarios/bench-model.toml (a TMC429 at 32 MHz, three axes moving in RAMP_MODE, the
//! Table 11-2 driver chain busy), in CLK cycles per second (docs/performance.md).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use tmc429_scenario::run::{run, Engine, Options};
use tmc429_scenario::scenario::parse;

/// The scenario, cut to `CYCLES` edges so that one iteration takes a fraction of a second.
const CYCLES: u64 = 1 << 23;

fn bench(c: &mut Criterion) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/scenarios/bench-model.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let mut sc = parse(&text, path).unwrap_or_else(|e| panic!("{path}: {e:?}"));
    sc.duration = CYCLES;
    let opt = Options::new(Engine::Model);
    let mut g = c.benchmark_group("scenario");
    g.throughput(Throughput::Elements(CYCLES));
    g.sample_size(10);
    g.bench_function("tmc429_bench_model_engine_model", |b| {
        b.iter(|| criterion::black_box(run(&sc, &opt, &mut |_, _| {}).unwrap().cycles))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
