//! Which vector instructions the DEM's force kernels run with, chosen at run time.
//!
//! The contact laws run on batches of contacts as columns (`contact::lanes`): plain loops
//! over the contacts, which the compiler turns into vector instructions as wide as the
//! function they are compiled in may use. The kernels are compiled once per [`Isa`] (the
//! generic x86-64 one, two lanes; AVX2, four; AVX-512, eight), and a DEM runs the widest the
//! processor has ([`Isa::widest`]) unless told otherwise (`riprap --isa`, [`Isa::set_default`],
//! or `Dem::isa`). So a portable build (no `target-cpu`) runs as wide as a native one.
//!
//! Every path gives the same bits: the laws use only IEEE-exact operations (add, multiply,
//! divide, square root, compare, select; Rust never fuses a multiply and an add on its own),
//! each contact's in the same order whatever the width (tested in `dem::forces`).
//!
//! What stays chosen at compile time: everything outside the kernels compiled per path (the
//! neighbour list, the walls' geometry, the flow solver), which a native build may still run
//! a little faster; and the closing kick's AVX2 form (`integrate::avx2`), written with AVX2
//! intrinsics and picked by the same choice.

use std::sync::atomic::{AtomicU8, Ordering};

use serde::{Deserialize, Serialize};

/// A set of vector instructions the force kernels are compiled for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Isa {
    /// What every processor of the target has (x86-64: SSE2, two f64 per instruction).
    Generic,
    /// x86-64 with AVX2 (four f64 per instruction).
    Avx2,
    /// x86-64 with AVX-512 F (eight f64 per instruction).
    Avx512,
}

/// The copies of a kernel as a const generic parameter (`Isa` is not one): a function compiled
/// into the AVX2 copy passes `AVX2` down to what it calls.
pub const GENERIC: u8 = 0;
/// See [`GENERIC`].
pub const AVX2: u8 = 1;
/// See [`GENERIC`].
pub const AVX512: u8 = 2;

/// The default set by [`Isa::set_default`]: `u8::MAX` while none is set.
static DEFAULT: AtomicU8 = AtomicU8::new(u8::MAX);

impl Isa {
    /// Every set, narrowest first.
    pub const ALL: [Isa; 3] = [Isa::Generic, Isa::Avx2, Isa::Avx512];

    /// Whether this processor runs the set.
    pub fn available(self) -> bool {
        match self {
            Isa::Generic => true,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => std::arch::is_x86_feature_detected!("avx2"),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => std::arch::is_x86_feature_detected!("avx512f"),
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The widest set this processor runs.
    pub fn widest() -> Isa {
        Isa::ALL
            .into_iter()
            .rev()
            .find(|i| i.available())
            .unwrap_or(Isa::Generic)
    }

    /// The set a new DEM runs: the one given to [`Isa::set_default`], else the widest.
    pub fn chosen() -> Isa {
        match DEFAULT.load(Ordering::Relaxed) {
            u8::MAX => Isa::widest(),
            k => Isa::ALL[k as usize],
        }
    }

    /// Makes `self` the set of every DEM built from now on in this process (`riprap --isa`);
    /// an error if the processor does not run it.
    pub fn set_default(self) -> anyhow::Result<()> {
        anyhow::ensure!(
            self.available(),
            "this processor does not run {} instructions (it runs up to {})",
            self.name(),
            Isa::widest().name()
        );
        let k = Isa::ALL.iter().position(|&i| i == self).expect("listed");
        DEFAULT.store(k as u8, Ordering::Relaxed);
        Ok(())
    }

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Isa::Generic => "generic",
            Isa::Avx2 => "avx2",
            Isa::Avx512 => "avx512",
        }
    }

    /// The set of command-line name `name`.
    pub fn named(name: &str) -> Option<Isa> {
        Isa::ALL.into_iter().find(|i| i.name() == name)
    }
}

/// Runs the copy of one function compiled for `$isa`: `$generic`, `$avx2` and `$avx512` call
/// the three copies, the last two declared with `#[target_feature(enable = "avx2")]` and
/// `#[target_feature(enable = "avx512f")]`. A set the processor lacks runs the generic copy
/// (the same bits), so a `Dem::isa` set by hand cannot run an instruction the processor
/// does not have.
macro_rules! on_isa {
    ($isa:expr, $generic:expr, $avx2:expr, $avx512:expr) => {
        match $isa {
            #[cfg(target_arch = "x86_64")]
            $crate::dem::isa::Isa::Avx2 if $crate::dem::isa::Isa::Avx2.available() => {
                // SAFETY: the processor has AVX2, checked just above.
                unsafe { $avx2 }
            }
            #[cfg(target_arch = "x86_64")]
            $crate::dem::isa::Isa::Avx512 if $crate::dem::isa::Isa::Avx512.available() => {
                // SAFETY: the processor has AVX-512 F, checked just above.
                unsafe { $avx512 }
            }
            _ => $generic,
        }
    };
}
pub(crate) use on_isa;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_widest_set_is_available_and_names_round_trip() {
        assert!(Isa::widest().available());
        assert!(Isa::Generic.available());
        for i in Isa::ALL {
            assert_eq!(Isa::named(i.name()), Some(i));
        }
        assert_eq!(Isa::named("sse4"), None);
    }
}
