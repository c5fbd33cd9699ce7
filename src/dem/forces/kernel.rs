//! What the force kernels share about the contact law: the pair kernel and the wall kernel
//! fill columns of contacts (`contact::lanes::Lanes`) and run one `contact::Law` on them,
//! chosen once per evaluation (`contact::dispatch`).

use super::super::material::{LawKind, PairLaw};

/// The law of every material pair. The laws of one `Dem` come from one `ContactModel`, so
/// they share a kind; a mix (set by hand through `Dem::laws`) is refused here, since the
/// kernels run one law on whole columns of contacts.
pub(super) fn uniform_kind(laws: &[PairLaw]) -> LawKind {
    let kind = laws.first().map_or(LawKind::Hertz, |l| l.kind());
    assert!(
        laws.iter().all(|l| l.kind() == kind),
        "the contact laws of one DEM must be of one kind (one `ContactModel`)"
    );
    kind
}
