//! Preconditions shared by several algorithms.

use crate::error::{Error, Result};
use crate::region::Region;

/// Precondition of every tour algorithm here: a non-empty region with one connected component
/// (a tour cannot leave a component).
pub(crate) fn connected(region: &Region) -> Result<()> {
    if region.is_empty() {
        return Err(Error::precondition("the region is empty"));
    }
    match crate::topology::components(region).count {
        1 => Ok(()),
        c => Err(Error::precondition(format!(
            "the region has {c} connected components; a tour needs one"
        ))),
    }
}
