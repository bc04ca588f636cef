//! Fixed-size tables of an enum's variants, made from strum's `VARIANTS` at compile time, so
//! that `for kind in Kind::ALL` iterates values and no list is kept by hand beside the enum.

/// `variants` as an array of `N` (strum's `EnumCount::COUNT`).
///
/// # Panics
/// At compile time, if `N` is not the number of variants.
#[must_use]
pub const fn array<T: Copy, const N: usize>(variants: &[T]) -> [T; N] {
    assert!(variants.len() == N, "N must be the number of variants");
    let mut out = [variants[0]; N];
    let mut i = 1;
    while i < N {
        out[i] = variants[i];
        i += 1;
    }
    out
}
