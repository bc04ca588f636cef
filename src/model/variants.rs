//! Name tables of the enums a config names by word (solver kinds, search methods, key
//! actions): strum derives the words; `named_variants!` gives each enum the same `ALL`,
//! `name` and `from_name`, and [`array()`] makes `ALL` a fixed-size array at compile time, so
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

/// `ALL` (every variant, in declaration order), `name` (its word in a config) and
/// `from_name` for an enum deriving strum's `IntoStaticStr`, `EnumString`, `VariantArray`
/// and `EnumCount`.
macro_rules! named_variants {
    ($t:ident) => {
        impl $t {
            /// Every variant, in the order the config documents them.
            pub const ALL: [$t; <$t as strum::EnumCount>::COUNT] =
                $crate::model::variants::array(<$t as strum::VariantArray>::VARIANTS);

            /// Its word in a config.
            #[must_use]
            pub fn name(self) -> &'static str {
                self.into()
            }

            /// The variant a config calls `name`.
            #[must_use]
            pub fn from_name(name: &str) -> Option<$t> {
                name.parse().ok()
            }
        }
    };
}
pub(crate) use named_variants;
