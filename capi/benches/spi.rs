//! The C path against the Rust path for the same SPI traffic (the C library's budget: at most 2× slower).
//!
//! Traffic: the start-up of examples/c (18 driver-RAM words, 32 LUT words, global parameters,
//! 7 registers for each of 3 motors), 10 read-backs and 8 status-only 8-bit reads: 90 frames,
//! SCK at 4 CLK per half period. Rust path: `Host::frame` on a chip without observer. C path:
//! `tmc429_spi_transfer`, the exported `extern "C"` function a C program calls (handle lookup,
//! catch_unwind, byte packing), with event decoding on (the default) and off.
//!
//! `cargo bench -p tmc429-capi --bench spi`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use tmc429::*;
use tmc429_model::host::Host;
use tmc429_model::Chip;

/// (value, bytes) frames.
fn traffic() -> Vec<(u32, usize)> {
    let mut t = Vec::new();
    for a in 0..18u32 {
        t.push(((0x40 + a) << 25 | 0x0510, 4));
    }
    for k in 0..32u32 {
        t.push(((0x60 + k) << 25 | 0x3F3F, 4));
    }
    t.push((0x3F << 25 | 0xF02, 4));
    for m in 0..3u32 {
        for (idx, v) in [(2, 1), (3, 1000), (12, 0x3706), (6, 100), (9, 0xBD09), (10, 0x300), (11, 0x100)] {
            t.push(((m << 4 | idx) << 25 | v, 4));
        }
    }
    for a7 in [0x02u32, 0x03, 0x06, 0x09, 0x0C, 0x39, 0x3F, 0x40, 0x5F, 0x7F] {
        t.push((a7 << 25 | 1 << 24, 4));
    }
    for _ in 0..8 {
        t.push((0, 1));
    }
    t
}

fn bench(c: &mut Criterion) {
    let t = traffic();
    assert_eq!(t.len(), 90);
    let mut g = c.benchmark_group("spi_90_frames");

    g.bench_function("rust_host_frame", |b| {
        b.iter(|| {
            let mut host = Host::new(Chip::Tmc429);
            host.set_sck_half(4).unwrap();
            let mut acc = 0u32;
            for &(v, n) in &t {
                acc ^= host.frame(v, 8 * n as u32);
            }
            black_box(acc)
        })
    });

    for (name, events) in [("c_spi_transfer_events_on", 1), ("c_spi_transfer_events_off", 0)] {
        let bytes: Vec<([u8; 4], usize)> = t
            .iter()
            .map(|&(v, n)| {
                let be = (v << (8 * (4 - n))).to_be_bytes();
                (be, n)
            })
            .collect();
        g.bench_function(name, |b| {
            // SAFETY: every pointer passed is valid for the length given.
            b.iter(|| unsafe {
                let mut h = 0u64;
                assert_eq!(tmc429_create(TMC429_CHIP_TMC429, 0, &mut h), TMC429_OK);
                assert_eq!(tmc429_set_sck_half(h, 4), TMC429_OK);
                assert_eq!(tmc429_events_enable(h, events), TMC429_OK);
                let mut acc = 0u8;
                let mut rx = [0u8; 4];
                for (tx, n) in &bytes {
                    tmc429_spi_transfer(h, tx.as_ptr(), rx.as_mut_ptr(), *n);
                    acc ^= rx[0] ^ rx[n - 1];
                }
                tmc429_destroy(h);
                black_box(acc)
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
