//! The registry of families and parameters: every name `gen`, configs and the manifest use.

use super::MAX_PIXELS;
use super::hole_lattice::Pattern;
use super::styles::Style;
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
    Eroded,
    HoleLattice,
    Comb,
    DoubleComb,
    Spiral,
    Windows,
    Outlines,
    Ring,
    CorridorStar,
    BoundaryRooms,
    ThinEulerian,
}

/// A generator parameter (the field of [`GenParams`](super::GenParams) of the same name).
/// The variants follow the rows of [`PARAMS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Param {
    N,
    Holes,
    Width,
    Height,
    K,
    Side,
    Parts,
    Style,
    Compactness,
    S,
    NoCut,
    Pattern,
}

/// The type of a parameter's values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// A non-negative integer.
    Count,
    /// A switch: `--no-cut` on the command line, `true` or `false` in a config.
    Flag,
    /// A [`Style`] name.
    Style,
    /// A number in [0, 1].
    Fraction,
    /// A [`Pattern`] name.
    Pattern,
}

impl ParamKind {
    /// What a value of this kind looks like, for messages.
    pub fn expected(self) -> &'static str {
        match self {
            ParamKind::Count => "a non-negative integer",
            ParamKind::Flag => "true or false",
            ParamKind::Style => "a style name",
            ParamKind::Fraction => "a number between 0 and 1",
            ParamKind::Pattern => "a pattern name",
        }
    }
}

/// One parameter: its names and meaning. The single declaration that `mowmill gen`'s flags,
/// the keys of a config's `[[family]]` tables, the `params` column of results and the
/// manifest are derived from.
#[derive(Debug)]
pub struct ParamSpec {
    pub param: Param,
    /// The config key and the key of `; params:` lines and of the `params` column.
    pub name: &'static str,
    /// The long flag of `mowmill gen` (without `--`).
    pub flag: &'static str,
    pub kind: ParamKind,
    /// The smallest and largest value of a [`ParamKind::Count`] parameter (inclusive); the
    /// largest is the generator's limit. A [`ParamKind::Fraction`] lies in [0, 1]. `mowmill
    /// gen` and configs both check values with [`ParamSpec::check`] before generating.
    pub min: usize,
    pub max: usize,
    pub help: &'static str,
}

/// Every parameter, indexed by `Param as usize`. The order is the order of the `params`
/// column of benchmark results, from which instance seeds derive: append, never reorder.
pub const PARAMS: [ParamSpec; 12] = [
    ParamSpec {
        param: Param::N,
        name: "n",
        flag: "n",
        kind: ParamKind::Count,
        min: 1,
        max: MAX_PIXELS,
        help: "Number of pixels",
    },
    ParamSpec {
        param: Param::Holes,
        name: "holes",
        flag: "holes",
        kind: ParamKind::Count,
        min: 0,
        // No limit of its own: more holes than pixels is refused with the pixel count.
        max: usize::MAX,
        help: "Number of holes (default 1 for random-holed, 0 otherwise)",
    },
    ParamSpec {
        param: Param::Width,
        name: "width",
        flag: "width",
        kind: ParamKind::Count,
        min: 1,
        max: MAX_PIXELS,
        help: "Width of the rectangle; corridor or bar width (1 or 2) of the structured families",
    },
    ParamSpec {
        param: Param::Height,
        name: "height",
        flag: "height",
        kind: ParamKind::Count,
        min: 1,
        max: MAX_PIXELS,
        help: "Height of the rectangle",
    },
    ParamSpec {
        param: Param::K,
        name: "k",
        flag: "k",
        kind: ParamKind::Count,
        min: 1,
        max: MAX_PIXELS,
        help: "Width of the annulus (donut), index of the band B_k (band), teeth (comb, double-comb), pane side (windows, default 2), rectangles (outlines), corridors 1-4 (corridor-star, default 4); hubs (hub-path) and paths (collinear-bridges) of the discrete families",
    },
    ParamSpec {
        param: Param::Side,
        name: "side",
        flag: "side",
        kind: ParamKind::Count,
        // A donut needs k ≥ 1 and side ≥ 2k + 1.
        min: 3,
        max: MAX_PIXELS,
        help: "Outer side of the annulus",
    },
    ParamSpec {
        param: Param::Parts,
        name: "parts",
        flag: "parts",
        kind: ParamKind::Count,
        min: 1,
        max: MAX_PIXELS,
        help: "Number of grass components (default 3)",
    },
    ParamSpec {
        param: Param::Style,
        name: "style",
        flag: "style",
        kind: ParamKind::Style,
        min: 0,
        max: 0,
        help: "Shape style (default: mixed, one of the others drawn from the seed); dense or sparse for eroded",
    },
    ParamSpec {
        param: Param::Compactness,
        name: "compactness",
        flag: "compactness",
        kind: ParamKind::Fraction,
        min: 0,
        max: 0,
        help: "Compactness of growth in [0, 1], 1 round, 0 ragged (default: drawn from the seed)",
    },
    ParamSpec {
        param: Param::S,
        name: "s",
        flag: "s",
        kind: ParamKind::Count,
        min: 0,
        // thin43 has 222 + 77s pixels.
        max: (MAX_PIXELS - 222) / 77,
        help: "Parameter s of the 4/3 thin example",
    },
    ParamSpec {
        param: Param::NoCut,
        name: "no_cut",
        flag: "no-cut",
        kind: ParamKind::Flag,
        min: 0,
        max: 0,
        help: "No cut vertices (random-simple) or no local cut vertices (random-holed)",
    },
    ParamSpec {
        param: Param::Pattern,
        name: "pattern",
        flag: "pattern",
        kind: ParamKind::Pattern,
        min: 0,
        max: 0,
        help: "Lattice of one-pixel holes: staggered (default), square, diagonal or sparse",
    },
];

impl ParamSpec {
    /// Checks one value: of the parameter's kind, a count within `min..=max`, a fraction a
    /// number in [0, 1] (not NaN). The one check of the values of `mowmill gen`'s flags and of
    /// a config's `[[family]]` keys.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the parameter, the bound and the value.
    pub fn check(&self, value: ParamValue) -> Result<()> {
        let name = self.name;
        let message = match (self.kind, value) {
            (ParamKind::Count, ParamValue::Count(v)) if v < self.min => {
                format!("expected {name} ≥ {}, got {v}", self.min)
            }
            (ParamKind::Count, ParamValue::Count(v)) if v > self.max => format!(
                "{name} = {v} is more than the generator's limit of {}",
                self.max
            ),
            (ParamKind::Fraction, ParamValue::Fraction(v)) if !(0.0..=1.0).contains(&v) => {
                format!("{name} must be between 0 and 1, got {v}")
            }
            (ParamKind::Count, ParamValue::Count(_))
            | (ParamKind::Fraction, ParamValue::Fraction(_))
            | (ParamKind::Flag, ParamValue::Flag(_))
            | (ParamKind::Style, ParamValue::Style(_))
            | (ParamKind::Pattern, ParamValue::Pattern(_)) => return Ok(()),
            _ => format!("{name}: expected {}, got {value}", self.kind.expected()),
        };
        Err(Error::invalid(message))
    }
}

impl Param {
    /// The parameter's row of [`PARAMS`].
    pub fn spec(self) -> &'static ParamSpec {
        &PARAMS[self as usize]
    }

    /// The key used in configs, in the `; params:` line and in messages.
    pub fn name(self) -> &'static str {
        self.spec().name
    }

    /// The parameter called `name` (a config key).
    pub fn from_name(name: &str) -> Option<Param> {
        PARAMS.iter().find(|s| s.name == name).map(|s| s.param)
    }

    /// The families that take this parameter.
    pub fn families(self) -> impl Iterator<Item = Family> {
        Family::ALL
            .into_iter()
            .filter(move |f| f.info().params.contains(&self))
    }
}

/// A parameter's value, of its [`ParamKind`]. It displays as in the `params` column
/// (`32`, `true`, `blob`, `0.5`) and serializes as the typed JSON value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamValue {
    Count(usize),
    Flag(bool),
    Style(Style),
    Fraction(f64),
    Pattern(Pattern),
}

impl fmt::Display for ParamValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamValue::Count(v) => write!(f, "{v}"),
            ParamValue::Flag(v) => write!(f, "{v}"),
            ParamValue::Style(v) => write!(f, "{v}"),
            ParamValue::Fraction(v) => write!(f, "{v}"),
            ParamValue::Pattern(v) => write!(f, "{v}"),
        }
    }
}

impl serde::Serialize for ParamValue {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match *self {
            ParamValue::Count(v) => s.serialize_u64(v as u64),
            ParamValue::Flag(v) => s.serialize_bool(v),
            ParamValue::Style(v) => s.serialize_str(v.name()),
            ParamValue::Fraction(v) => s.serialize_f64(v),
            ParamValue::Pattern(v) => s.serialize_str(v.name()),
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
    /// Whether the instance depends on the seed (`mowmill gen` then requires `--seed`).
    pub random: bool,
    /// A structured family: a shape the papers' proofs find hardest, built to stress
    /// them; a claim "holds" only with decided instances of one (docs/claims.md).
    pub structured: bool,
}

/// The registry, indexed by `Family as usize`. A new family adds a variant, a row here and an
/// arm in `Spec::build`; `mowmill gen`, configs and the manifest read it from here.
pub(super) const FAMILY_TABLE: [FamilyInfo; 22] = [
    FamilyInfo {
        family: Family::Rect,
        name: "rect",
        summary: "the full width x height rectangle",
        params: &[Param::Width, Param::Height],
        required: &[Param::Width, Param::Height],
        random: false,
        structured: false,
    },
    FamilyInfo {
        family: Family::RandomSimple,
        name: "random-simple",
        summary: "exactly n pixels, 4-connected, no holes; no_cut: no cut vertices",
        params: &[Param::N, Param::NoCut, Param::Style, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: false,
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
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::Thin,
        name: "thin",
        summary: "thin pocket: width-1 corridors, no 2x2 block, exactly n pixels and `holes` holes",
        params: &[Param::N, Param::Holes, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::LawnScattered,
        name: "lawn-scattered",
        summary: "n pixels of grass in `parts` components, 8-separated from one another",
        params: &[Param::N, Param::Parts, Param::Style, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::Donut,
        name: "donut",
        summary: "square annulus of outer side `side` and width k",
        params: &[Param::Side, Param::K],
        required: &[Param::Side, Param::K],
        random: false,
        structured: false,
    },
    FamilyInfo {
        family: Family::Band,
        name: "band",
        summary: "diagonal band B_k: 0 <= x, y <= k + 1, |x - y| <= 2 (tight for 6/5, milling paper)",
        params: &[Param::K],
        required: &[Param::K],
        random: false,
        structured: false,
    },
    FamilyInfo {
        family: Family::Thin43,
        name: "thin43",
        summary: "the 4/3 thin example (turn-cost paper, Fig. 6) with parameter s >= 0",
        params: &[Param::S],
        required: &[Param::S],
        random: false,
        structured: false,
    },
    FamilyInfo {
        family: Family::Boundary,
        name: "boundary",
        summary: "every pixel a boundary pixel (the precondition of boundary-cc): stairs, one-pixel links and parts, holes",
        params: &[Param::N, Param::Style, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::ThinArms,
        name: "thin-arms",
        summary: "thin pocket grown pixel by pixel: stairs, crossings with short arms, exactly n pixels and `holes` holes",
        params: &[Param::N, Param::Holes, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: true,
    },
    FamilyInfo {
        family: Family::Pinholes,
        name: "pinholes",
        summary: "exactly n pixels, exactly `holes` one-pixel holes, often in columns, walls down to one pixel",
        params: &[Param::N, Param::Holes, Param::Style, Param::Compactness],
        required: &[Param::N, Param::Holes],
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::Eroded,
        name: "eroded",
        summary: "a square of side ~sqrt(3n) eroded at random to n pixels (a 2016 thesis's process), 4-connected; style dense or sparse (holes)",
        params: &[Param::N, Param::Style],
        required: &[Param::N],
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::HoleLattice,
        name: "hole-lattice",
        summary: "structured: odd square riddled with one-pixel holes in a lattice (staggered: Q = 0, h ~ N/3; milling25 -> 8/3)",
        params: &[Param::N, Param::Pattern],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    FamilyInfo {
        family: Family::Comb,
        name: "comb",
        summary: "structured: a spine with k width-1 teeth at spacing 2 on one side, N = 2k - 1 + kL",
        params: &[Param::N, Param::K],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    FamilyInfo {
        family: Family::DoubleComb,
        name: "double-comb",
        summary: "structured: a spine with k width-1 teeth at spacing 2 on both sides, N = 2k - 1 + 2kL",
        params: &[Param::N, Param::K],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    FamilyInfo {
        family: Family::Spiral,
        name: "spiral",
        summary: "structured: a corridor of width 1 or 2 wound as a rectangular spiral, windings one cell apart",
        params: &[Param::N, Param::Width],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    FamilyInfo {
        family: Family::Windows,
        name: "windows",
        summary: "structured: a square with an m x m lattice of k x k panes (holes), bars of width 1 or 2",
        params: &[Param::N, Param::Width, Param::K],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    FamilyInfo {
        family: Family::Outlines,
        name: "outlines",
        summary: "structured: union of k crossing width-1 rectangle outlines, connected, thin, every pixel of even degree",
        params: &[Param::N, Param::K],
        required: &[Param::N],
        random: true,
        structured: true,
    },
    FamilyInfo {
        family: Family::Ring,
        name: "ring",
        summary: "structured: a rectangular ring (annulus) of width 1 or 2, N = 2w(a + b) - 4w^2",
        params: &[Param::N, Param::Width],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    FamilyInfo {
        family: Family::CorridorStar,
        name: "corridor-star",
        summary: "structured: k = 1..4 straight corridors (axes, diagonals) of width 1 or 2 crossing at a centre",
        params: &[Param::N, Param::K, Param::Width],
        required: &[Param::N],
        random: false,
        structured: true,
    },
    // The two large-scale families (10^6 to 10^7 pixels in seconds) for boundary-cc and
    // thin-euler, whose small families `boundary` and `outlines` do not scale.
    FamilyInfo {
        family: Family::BoundaryRooms,
        name: "boundary-rooms",
        summary: "every pixel a boundary pixel, at any size (linear time): rooms on a random tree with pinholes, notches, stairs, one-pixel links, holes",
        params: &[Param::N, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: false,
    },
    FamilyInfo {
        family: Family::ThinEulerian,
        name: "thin-eulerian",
        summary: "thin, every pixel of even degree, at any size (linear time): outlines of random rectangles added mod 2, crossings, holes; n within n/50 + 32",
        params: &[Param::N, Param::Compactness],
        required: &[Param::N],
        random: true,
        structured: false,
    },
];

impl FamilyInfo {
    /// Refuses a parameter the family does not take (shared by `mowmill gen` and configs).
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the parameter and the ones the family takes.
    pub fn check_takes(&self, param: Param) -> Result<()> {
        if self.params.contains(&param) {
            return Ok(());
        }
        let takes: Vec<&str> = self.params.iter().map(|q| q.name()).collect();
        Err(Error::invalid(format!(
            "parameter `{}` does not apply to family {} (it takes: {})",
            param.name(),
            self.name,
            takes.join(", ")
        )))
    }

    /// Refuses a request without one of the family's required parameters; `given` says which
    /// parameters have a value.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first missing parameter.
    pub fn check_required(&self, given: impl Fn(Param) -> bool) -> Result<()> {
        match self.required.iter().find(|&&q| !given(q)) {
            Some(q) => Err(Error::invalid(format!(
                "family {} needs parameter `{}`",
                self.name,
                q.name()
            ))),
            None => Ok(()),
        }
    }
}

impl Family {
    pub const ALL: [Family; 22] = [
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
        Family::Eroded,
        Family::HoleLattice,
        Family::Comb,
        Family::DoubleComb,
        Family::Spiral,
        Family::Windows,
        Family::Outlines,
        Family::Ring,
        Family::CorridorStar,
        Family::BoundaryRooms,
        Family::ThinEulerian,
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

/// The families, their parameters and the styles, for `mowmill gen --help`: one line per
/// family with its required parameters, `[optional]` ones, and whether it needs a seed.
pub fn families_help() -> String {
    let mut out = String::from("Families (parameters; [optional]):\n");
    for f in Family::ALL {
        let info = f.info();
        let params: Vec<String> = info
            .params
            .iter()
            .map(|q| {
                let flag = format!("--{}", q.spec().flag);
                if info.required.contains(q) {
                    flag
                } else {
                    format!("[{flag}]")
                }
            })
            .collect();
        let seed = if info.random { " --seed" } else { "" };
        out.push_str(&format!(
            "  {:<15} {}{seed}\n  {:<15}   {}\n",
            info.name,
            params.join(" "),
            "",
            info.summary
        ));
    }
    let styles: Vec<&str> = Style::ALL.iter().map(|s| s.name()).collect();
    let eroded: Vec<&str> = Style::ERODED.iter().map(|s| s.name()).collect();
    let fixed: Vec<&str> = FAMILY_TABLE
        .iter()
        .filter(|f| !f.random)
        .map(|f| f.name)
        .collect();
    out.push_str(&format!(
        "\nStyles (--style): {} (eroded: {}, mixed draws one).\nPatterns (--pattern, hole-lattice): {}.\nDeterministic families (--seed optional, default 0): {}.",
        styles.join(", "),
        eroded.join(", "),
        Pattern::NAMES.join(", "),
        fixed.join(", ")
    ));
    out
}
