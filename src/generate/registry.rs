use crate::error::Error;
use crate::error::Result;
use std::fmt;
use std::str::FromStr;

/// An instance family; its stable name is the CLI's `mowmill gen FAMILY`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Family {
    Rect,
    RandomSimple,
    RandomHoled,
    Thin,
    LawnScattered,
    Donut,
    Band,
    Thin43,
    Boundary,
    ThinArms,
    Pinholes,
}

/// A generator parameter (the field of [`GenParams`] of the same name).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Param {
    N,
    Holes,
    Width,
    Height,
    Side,
    K,
    Parts,
    NoCut,
    Style,
    Compactness,
    S,
}

impl Param {
    pub const ALL: [Param; 11] = [
        Param::N,
        Param::Holes,
        Param::Width,
        Param::Height,
        Param::Side,
        Param::K,
        Param::Parts,
        Param::NoCut,
        Param::Style,
        Param::Compactness,
        Param::S,
    ];

    /// The key used in the `; params:` line and in messages.
    pub fn name(self) -> &'static str {
        match self {
            Param::N => "n",
            Param::Holes => "holes",
            Param::Width => "width",
            Param::Height => "height",
            Param::Side => "side",
            Param::K => "k",
            Param::Parts => "parts",
            Param::NoCut => "no_cut",
            Param::Style => "style",
            Param::Compactness => "compactness",
            Param::S => "s",
        }
    }
}

/// One row of the family registry: name, one-line summary, and the parameters it takes.
#[derive(Debug)]
pub struct FamilyInfo {
    pub family: Family,
    /// Stable name (CLI and `; family:` line).
    pub name: &'static str,
    pub summary: &'static str,
    /// The parameters the family takes, in the order of the `; params:` line.
    pub params: &'static [Param],
    /// The parameters without a default.
    pub required: &'static [Param],
}

/// The registry, indexed by `Family as usize`. A new family adds a variant, a row here and an
/// arm in `build`.
pub(super) const FAMILY_TABLE: [FamilyInfo; 11] = [
    FamilyInfo {
        family: Family::Rect,
        name: "rect",
        summary: "the full width x height rectangle",
        params: &[Param::Width, Param::Height],
        required: &[Param::Width, Param::Height],
    },
    FamilyInfo {
        family: Family::RandomSimple,
        name: "random-simple",
        summary: "exactly n pixels, 4-connected, no holes; no_cut: no cut vertices",
        params: &[Param::N, Param::NoCut, Param::Style, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::RandomHoled,
        name: "random-holed",
        summary: "exactly n pixels, 4-connected, exactly `holes` holes; no_cut: no local cut vertices",
        params: &[
            Param::N,
            Param::Holes,
            Param::NoCut,
            Param::Style,
            Param::Compactness,
        ],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::Thin,
        name: "thin",
        summary: "thin pocket: width-1 corridors, no 2x2 block, exactly n pixels and `holes` holes",
        params: &[Param::N, Param::Holes, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::LawnScattered,
        name: "lawn-scattered",
        summary: "n pixels of grass in `parts` components, 8-separated from one another",
        params: &[Param::N, Param::Parts, Param::Style, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::Donut,
        name: "donut",
        summary: "square annulus of outer side `side` and width k",
        params: &[Param::Side, Param::K],
        required: &[Param::Side, Param::K],
    },
    FamilyInfo {
        family: Family::Band,
        name: "band",
        summary: "diagonal band B_k: 0 <= x, y <= k + 1, |x - y| <= 2 (tight for 6/5, milling paper)",
        params: &[Param::K],
        required: &[Param::K],
    },
    FamilyInfo {
        family: Family::Thin43,
        name: "thin43",
        summary: "the 4/3 thin example (turn-cost paper, Fig. 6) with parameter s >= 0",
        params: &[Param::S],
        required: &[Param::S],
    },
    FamilyInfo {
        family: Family::Boundary,
        name: "boundary",
        summary: "every pixel a boundary pixel (the precondition of boundary-cc): stairs, one-pixel links and parts, holes",
        params: &[Param::N, Param::Style, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::ThinArms,
        name: "thin-arms",
        summary: "thin pocket grown pixel by pixel: stairs, crossings with short arms, exactly n pixels and `holes` holes",
        params: &[Param::N, Param::Holes, Param::Compactness],
        required: &[Param::N],
    },
    FamilyInfo {
        family: Family::Pinholes,
        name: "pinholes",
        summary: "exactly n pixels, exactly `holes` one-pixel holes, often in columns, walls down to one pixel",
        params: &[Param::N, Param::Holes, Param::Style, Param::Compactness],
        required: &[Param::N, Param::Holes],
    },
];

impl Family {
    pub const ALL: [Family; 11] = [
        Family::Rect,
        Family::RandomSimple,
        Family::RandomHoled,
        Family::Thin,
        Family::LawnScattered,
        Family::Donut,
        Family::Band,
        Family::Thin43,
        Family::Boundary,
        Family::ThinArms,
        Family::Pinholes,
    ];

    /// The family's registry row.
    pub fn info(self) -> &'static FamilyInfo {
        &FAMILY_TABLE[self as usize]
    }

    pub fn name(self) -> &'static str {
        self.info().name
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Family {
    type Err = Error;

    fn from_str(s: &str) -> Result<Family> {
        Family::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                Error::invalid(format!(
                    "unknown family {s:?}: expected one of {}",
                    names.join(", ")
                ))
            })
    }
}
