//! The 4/3 thin example of Fig. 6 and Theorem 5.9 of the turn-cost paper (mowmill's
//! reconstruction): gadgets whose exact cycle covers merge only at a cost.

use super::*;
use crate::algorithms::merge::merge_cycles;
use crate::generate::thin43_gadgets;

/// The gadget cycle cover of `thin43`: each gadget's own minimum-turn cycle cover (exact
/// `cc-turns` on the gadget alone), all together. Where a gadget's optimal cover has several
/// cycles (Y_j: the two rectangles on either side of its chord), they are merged within the
/// gadget when that is free, so that each gadget is one cycle as in the reconstruction.
pub(crate) fn thin43_gadget_cover(s: usize, time_limit: f64) -> Result<CycleCover> {
    let mut cycles = Vec::new();
    for (name, pixels) in thin43_gadgets(s) {
        let gadget = Region::from_pixels(pixels)?;
        let (value, _, cover) = exact_solve(&gadget, ExactObjective::CcTurns, time_limit);
        match (value, cover) {
            (Some(_), Some(c)) => {
                let (merged, _) = merge_cycles(&gadget, &c, Merge::Smart);
                let free = check(&gadget, &merged, Mode::Milling).turns
                    == check(&gadget, &c, Mode::Milling).turns;
                cycles.extend(if free { merged.cycles } else { c.cycles });
            }
            _ => {
                return Err(Error::invalid(format!(
                    "thin43 gadget {name}: the exact cycle cover was not proven in {time_limit} s"
                )));
            }
        }
    }
    Ok(CycleCover::new(cycles))
}

/// All measurements of `thin43` with parameter s.
pub fn thin43(s: usize, opts: &TightOptions) -> Result<Member> {
    let region = family_region(&GenParams {
        s: Some(s),
        ..GenParams::new(Family::Thin43, 0)
    })?;
    let member = format!("s={s}");
    let ss = s as u64;
    let n = region.len() as u64;
    let (opt_value, heur_value) = (12 * ss + 32, 16 * ss + 38);
    let mut r = Rows {
        family: "thin43",
        member: &member,
        param: ss,
        n,
        rows: Vec::new(),
    };
    r.claim(
        "n",
        format!("222 + 77s = {}", 222 + 77 * ss),
        (222 + 77 * ss) as f64,
        f(n),
        Standing::Established,
        "pixel count",
        FIG6,
    );
    let (opt_cc, _, _) = exact_solve(&region, ExactObjective::CcTurns, opts.time_limit);
    r.claim(
        "opt_cc_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        opt_cc.map(|v| v as f64),
        Standing::Established,
        "exact cc-turns (proven optimal)",
        FIG6,
    );
    let (opt_tour, tour_lb, opt_cover) =
        exact_solve(&region, ExactObjective::Turns, opts.time_limit);
    r.claim(
        "opt_tour_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        opt_tour.map(|v| v as f64),
        Standing::Established,
        &if opt_tour.is_some() {
            "exact turns (proven optimal)".to_string()
        } else {
            format!("exact turns hit the time limit (lower bound {tour_lb})")
        },
        FIG6,
    );
    let (_, thin_cc) = run_algorithm(&region, "thin-cc", Merge::Smart, AlgoObjective::CcTurns)?;
    r.claim(
        "thin_cc_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        f(thin_cc.turns),
        Standing::Established,
        "thin-cc (Corollary 5.3; checker)",
        FIG6,
    );
    let gadget_cover = thin43_gadget_cover(s, opts.time_limit)?;
    let gadgets = checked(&region, &gadget_cover, "the thin43 gadget cover")?;
    r.claim(
        "gadget_cc_turns",
        format!("12s + 32 = {opt_value}"),
        opt_value as f64,
        f(gadgets.turns),
        Standing::Established,
        "each gadget's exact cycle cover (checker)",
        FIG6,
    );
    r.claim(
        "gadget_cc_cycles",
        format!("2s + 4 = {}", 2 * ss + 4),
        (2 * ss + 4) as f64,
        Some(gadgets.cycles as f64),
        Standing::Established,
        "each gadget's exact cycle cover (checker)",
        FIG6,
    );
    let (naive_cover, naive_stats) = merge_cycles(&region, &gadget_cover, Merge::Naive);
    let naive = checked(&region, &naive_cover, "the naive merge of the gadget cover")?;
    r.claim(
        "gadget_naive_turns",
        format!("16s + 38 = {heur_value}"),
        heur_value as f64,
        f(naive.turns),
        Standing::Example,
        &format!(
            "gadget cover, --merge naive ({} of {} merges free)",
            naive_stats.free_merges, naive_stats.merges
        ),
        FIG6,
    );
    let (smart_cover, smart_stats) = merge_cycles(&region, &gadget_cover, Merge::Smart);
    let smart = checked(&region, &smart_cover, "the smart merge of the gadget cover")?;
    r.report(
        "gadget_smart_turns",
        "what smart merging achieves from the gadget cover".to_string(),
        f(smart.turns),
        &format!(
            "gadget cover, --merge smart ({} of {} merges free)",
            smart_stats.free_merges, smart_stats.merges
        ),
        FIG6,
    );
    let (_, default_merge) =
        run_algorithm(&region, "thin-merge", Merge::Smart, AlgoObjective::Turns)?;
    r.report(
        "thin_merge_turns",
        "thin-merge as registered (from thin-cc's cover)".to_string(),
        f(default_merge.turns),
        "thin-merge (checker)",
        FIG6,
    );
    let opt = opt_tour.unwrap_or(opt_value);
    r.report(
        "ratio_gadget_naive",
        "gadget naive merge / OPT -> 4/3".to_string(),
        ratio(naive.turns, opt),
        "gadget_naive_turns / opt_tour_turns",
        FIG6,
    );
    r.report(
        "ratio_thin_merge",
        "thin-merge / OPT (Theorem 5.9: <= 4/3)".to_string(),
        ratio(default_merge.turns, opt),
        "thin_merge_turns / opt_tour_turns",
        FIG6,
    );
    let rows = r.rows;
    Ok(Member {
        family: "thin43",
        member,
        param: ss,
        region,
        rows,
        drawings: vec![
            (
                format!("gadget cover, naive merge: {} turns", naive.turns),
                naive_cover,
            ),
            (
                format!("optimal tour: {} turns", opt_tour.unwrap_or(opt_value)),
                opt_cover.unwrap_or_default(),
            ),
        ],
    })
}
