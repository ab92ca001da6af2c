//! Model speed: three axes in RAMP_MODE through `tick()`, in CLK cycles per second
//! (target ≥ 30 M/s; docs/performance.md).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use tmc429_model::host::Host;
use tmc429_model::pmulpdiv;
use tmc429_model::regmap::motor_a7;
use tmc429_model::{Chip, Inputs, Tmc429};

const CYCLES: u64 = 1 << 20;

/// Three axes moving back and forth in RAMP_MODE with the datasheet's parameters.
fn three_axes(chip: Chip) -> Tmc429 {
    let mut h = Host::new(chip);
    let p = pmulpdiv::calc(1000, 3, 3, 0.01).register_value().unwrap();
    for m in 0..3u8 {
        h.write(motor_a7(m, 12), 3 << 12 | 3 << 8 | 4);
        h.write(motor_a7(m, 2), 1);
        h.write(motor_a7(m, 3), 2047);
        h.write(motor_a7(m, 6), 1000);
        h.write(motor_a7(m, 9), p);
        h.write(motor_a7(m, 10), 0);
        // Far targets: the axes accelerate and then run at v_max for the whole measurement.
        h.write(motor_a7(m, 0), 4_000_000 + 10_000 * m as u32);
    }
    h.into_chip()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("model");
    g.throughput(Throughput::Elements(CYCLES));
    for chip in [Chip::Tmc428, Chip::Tmc429] {
        let mut t = three_axes(chip);
        let idle = Inputs::default();
        g.bench_function(format!("{chip}_three_axes_ramp_mode"), |b| {
            b.iter(|| {
                for _ in 0..CYCLES {
                    criterion::black_box(t.tick(criterion::black_box(&idle)));
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
