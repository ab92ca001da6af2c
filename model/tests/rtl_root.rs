//! The square-root arithmetic of the RTL's target velocity unit (`rtl/tmc429_vroot.v`, the
//! running steps of `ROOT_SPEC` 0, docs/rtl.md "The target-velocity pipeline"; the law is C50)
//! gives the model's `isqrt` for every radicand it is loaded with: 28 bits, two steps from the
//! load's table, then six cycles of two non-restoring steps on a 16-bit two's-complement
//! remainder.

use tmc429_model::vroot::isqrt;

/// The load's two steps from remainder and root 0 over the four top radicand bits: (restoring
/// remainder, root), the table `sqrt_ld` of the RTL.
fn load(s4: u32) -> (u32, u32) {
    let q = isqrt(u64::from(s4)) as u32;
    (s4 - q * q, q)
}

/// One non-restoring step as the RTL forms it: {R, s} + {y XOR !sign, 11} modulo 2^16, the new
/// root bit 1 when the result's sign is 0. `r` is the 16-bit remainder, `y` the 14-bit root.
fn step(r: u32, y: u32, s: u32) -> (u32, u32) {
    let neg = (r >> 15) & 1;
    let operand = ((y ^ if neg == 1 { 0 } else { 0x3FFF }) << 2) | 3;
    let r = ((((r & 0x3FFF) << 2) | s) + operand) & 0xFFFF;
    let bit = !(r >> 15) & 1;
    (r, ((y << 1) | bit) & 0x3FFF)
}

fn root(radicand: u32) -> u32 {
    let (mut r, mut y) = load(radicand >> 24);
    for pair in (0..12).rev() {
        (r, y) = step(r, y, (radicand >> (2 * pair)) & 3);
    }
    y
}

#[test]
fn the_load_table_is_the_rtl_table() {
    // {r[2:0], y[1:0]} of sqrt_ld for s4 = 0..15
    let table =
        [(0, 0), (0, 1), (1, 1), (2, 1), (0, 2), (1, 2), (2, 2), (3, 2), (4, 2), (0, 3), (1, 3), (2, 3), (3, 3), (4, 3), (5, 3), (6, 3)];
    for (s4, want) in table.iter().enumerate() {
        assert_eq!(load(s4 as u32), *want, "s4 = {s4}");
    }
}

#[test]
fn non_restoring_steps_give_isqrt_for_every_28_bit_radicand() {
    let mut wrong = Vec::new();
    for radicand in 0u32..1 << 28 {
        let want = isqrt(u64::from(radicand)) as u32;
        if root(radicand) != want && wrong.len() < 5 {
            wrong.push((radicand, root(radicand), want));
        }
    }
    assert!(wrong.is_empty(), "(radicand, root, isqrt): {wrong:?}");
}

#[test]
fn the_largest_radicand_and_a_perfect_square_are_exact() {
    assert_eq!(root((1 << 28) - 1), 16383);
    assert_eq!(root(16383 * 16383), 16383);
    assert_eq!(root(16383 * 16383 - 1), 16382);
    assert_eq!(root(0), 0);
}
