//! CLK cycles per second of the Verilated RTL alone, of the lock-step pair (model + RTL +
//! comparison) on pre-generated pin stimulus — on two threads as `tmc429 cosim` runs it
//! ([`tmc429_testbench::pair::run_pair`]) and on one — and of the whole `tmc429 cosim` loop
//! (stimulus generation, transaction log, coverage; two threads). Results:
//! docs/performance.md.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};

use tmc429_model::{Chip, Inputs, Tmc429};
use tmc429_testbench::pair::{run_pair, BATCH};
use tmc429_testbench::rtl::Expected;
use tmc429_testbench::signals::{agree, Compare};
use tmc429_testbench::stimulus::{Driver, Profile, Stimulus};
use tmc429_testbench::{run, Config, Rtl, Variant};

const CYCLES: usize = 200_000;

/// The regression's pin stimulus for `n` cycles.
fn inputs(chip: Chip, n: usize) -> Vec<Inputs> {
    let mut stim = Stimulus::new(chip, Profile::Motion, 1);
    let mut drv = Driver::default();
    (0..n)
        .map(|_| {
            if drv.ready() {
                drv.start(stim.next_txn());
            }
            drv.step().0
        })
        .collect()
}

type Group<'a> = criterion::BenchmarkGroup<'a, criterion::measurement::WallTime>;

/// The Verilated RTL alone, stepped through the inputs.
fn rtl_alone(g: &mut Group, chip: Chip, inp: &[Inputs]) {
    g.bench_function("rtl_alone_tmc429", |b| {
        b.iter(|| {
            let mut rtl = Rtl::new(Variant::Chip(chip));
            for i in inp {
                black_box(rtl.tick(i));
            }
            black_box(rtl.probes());
        })
    });
}

/// The lock-step pair as `tmc429 cosim` runs it: the model in this thread, the RTL and the
/// comparison in a second one (`run_pair`).
fn lockstep_pair(g: &mut Group, chip: Chip, inp: &[Inputs]) {
    g.bench_function("lockstep_pair_tmc429", |b| {
        let mask = Compare::all();
        b.iter(|| {
            let mut model = Tmc429::new(chip);
            let reset = (model.outputs(), model.probes());
            let mut rest = inp.chunks(BATCH);
            let first = run_pair(Variant::Chip(chip), mask, reset, |buf| {
                let Some(chunk) = rest.next() else { return false };
                for i in chunk {
                    let out = model.tick(i);
                    buf.push(Expected::new(i, &out, &model.probes()));
                }
                true
            })
            .unwrap();
            assert_eq!(first, None);
        })
    });
}

/// The pair in one thread: model, RTL and comparison one after the other in every cycle.
fn lockstep_pair_1thread(g: &mut Group, chip: Chip, inp: &[Inputs]) {
    g.bench_function("lockstep_pair_1thread_tmc429", |b| {
        let mask = Compare::all();
        b.iter(|| {
            let mut model = Tmc429::new(chip);
            let mut rtl = Rtl::new(Variant::Chip(chip));
            let mut bad = 0u32;
            for i in inp {
                let mo = model.tick(i);
                let ro = rtl.tick(i);
                if !agree(mask, &mo, &model.probes(), &ro, &rtl.probes()) {
                    bad += 1;
                }
            }
            assert_eq!(bad, 0);
        })
    });
}

fn bench(c: &mut Criterion) {
    let chip = Chip::Tmc429;
    let inp = inputs(chip, CYCLES);
    let mut g = c.benchmark_group("cosim");
    g.throughput(Throughput::Elements(CYCLES as u64));
    g.sample_size(10);
    rtl_alone(&mut g, chip, &inp);
    lockstep_pair(&mut g, chip, &inp);
    lockstep_pair_1thread(&mut g, chip, &inp);
    // the whole `tmc429 cosim` loop: stimulus, pin driver, both sides
    g.bench_function("cosim_run_tmc429", |b| {
        b.iter(|| {
            let out = run(&Config::new(chip, 1, CYCLES as u64)).unwrap();
            assert!(out.mismatch.is_none());
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
