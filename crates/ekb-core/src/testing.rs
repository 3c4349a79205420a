//! For tests only (here and in the crates above): no part of the library's API.

/// `count` pseudo-random 64-bit values, the same every run (xorshift64).
pub fn random_bits(count: usize) -> impl Iterator<Item = u64> {
    std::iter::successors(Some(0x9E37_79B9_7F4A_7C15_u64), |&bits| {
        let bits = bits ^ (bits << 13);
        let bits = bits ^ (bits >> 7);
        Some(bits ^ (bits << 17))
    })
    .skip(1)
    .take(count)
}
