//! The donut of Fig. 5 of the turn-cost paper: the strip cover, the optimal cycle cover (concentric
//! rings) and tour (a spiral), and what the merge strategies make of the matching cycle cover.

use super::*;

/// The 4k concentric rings of the donut: an optimal cycle cover (4 turns each).
pub fn donut_rings(side: usize, k: usize) -> CycleCover {
    let l = side as i32;
    CycleCover::new(
        (0..k as i32)
            .map(|i| rectangle_walk(i, i, l - 1 - i, l - 1 - i))
            .collect(),
    )
}

/// The boundary walk of the rectangle with corners (x0, y0) and (x1, y1), counter-clockwise
/// from (x0, y0).
fn rectangle_walk(x0: i32, y0: i32, x1: i32, y1: i32) -> Walk {
    let mut w = Vec::new();
    w.extend((x0..x1).map(|x| Pixel::new(x, y0)));
    w.extend((y0..y1).map(|y| Pixel::new(x1, y)));
    w.extend((x0 + 1..=x1).rev().map(|x| Pixel::new(x, y1)));
    w.extend((y0 + 1..=y1).rev().map(|y| Pixel::new(x0, y)));
    w
}

/// The spiral tour of the donut with 4k + 2 turns (Fig. 5(b)), for k ≥ 2: ring i (the
/// boundary of the square [i, L−1−i]²) is run counter-clockwise from (i, i) and left at
/// (i, i+1) eastwards into ring i + 1 (4 turns per ring); the innermost ring continues down
/// column k−1 to row 0 and west back to (0, 0), where a U-turn closes the tour:
/// 4(k−1) + 3 + 1 + 2 = 4k + 2 turns.
pub fn donut_spiral(side: usize, k: usize) -> CycleCover {
    let (l, k) = (side as i32, k as i32);
    let mut w: Walk = Vec::new();
    for i in 0..k {
        let (lo, hi) = (i, l - 1 - i);
        w.extend((lo..hi).map(|x| Pixel::new(x, lo)));
        w.extend((lo..hi).map(|y| Pixel::new(hi, y)));
        w.extend((lo + 1..=hi).rev().map(|x| Pixel::new(x, hi)));
        if i + 1 < k {
            // Down column i to row i + 1, then east into ring i + 1 at (i + 1, i + 1).
            w.extend((lo + 2..=hi).rev().map(|y| Pixel::new(lo, y)));
            w.push(Pixel::new(lo, lo + 1));
        } else {
            // Down column k − 1 to row 0, then west along row 0 to (1, 0).
            w.extend((1..=hi).rev().map(|y| Pixel::new(lo, y)));
            w.extend((1..=lo).rev().map(|x| Pixel::new(x, 0)));
        }
    }
    CycleCover::tour(w)
}

/// All measurements of the donut of width k and outer side `side`.
pub fn donut(side: usize, k: usize, opts: &TightOptions) -> Result<Member> {
    let region = family_region(&GenParams {
        side: Some(side),
        k: Some(k),
        ..GenParams::new(Family::Donut, 0)
    })?;
    let member = format!("k={k} L={side}");
    let kk = k as u64;
    let mut r = Rows {
        family: "donut",
        member: &member,
        param: kk,
        n: region.len() as u64,
        rows: Vec::new(),
    };
    let s = min_strip_cover_size(&region) as u64;
    r.claim(
        "strip_cover",
        format!("4k = {}", 4 * kk),
        (4 * kk) as f64,
        f(s),
        Standing::Established,
        "Hopcroft-Karp + König (Lemma 4.4)",
        FIG5,
    );
    // The optimal cycle cover: 4k concentric rings, each 4 turns.
    let rings = checked(&region, &donut_rings(side, k), "the donut rings")?;
    let (opt_cc, _, _) = exact_solve(&region, ExactObjective::CcTurns, opts.time_limit);
    r.claim(
        "rings_cc_turns",
        format!("k rings of 4 turns = {}", 4 * kk),
        (4 * kk) as f64,
        f(rings.turns),
        Standing::Established,
        "explicit concentric rings (checker)",
        FIG5,
    );
    r.claim(
        "opt_cc_turns",
        format!("4k = {}", 4 * kk),
        (4 * kk) as f64,
        opt_cc.map(|v| v as f64),
        Standing::Established,
        "exact cc-turns (proven optimal)",
        FIG5,
    );
    // The optimal tour: a spiral with 4k + 2 turns; the exact solver for small k.
    let spiral_cover = donut_spiral(side, k);
    let spiral = checked(&region, &spiral_cover, "the donut spiral")?;
    r.claim(
        "spiral_turns",
        format!("4k + 2 = {}", 4 * kk + 2),
        (4 * kk + 2) as f64,
        f(spiral.turns),
        Standing::Established,
        "explicit spiral (checker)",
        FIG5,
    );
    let mut opt_tour_cover = spiral_cover.clone();
    let opt_tour = if k <= opts.donut_exact_k {
        let (value, lb, cover) = exact_solve(&region, ExactObjective::Turns, opts.time_limit);
        match value {
            Some(v) => {
                r.claim(
                    "opt_tour_turns",
                    format!("4k + 2 = {}", 4 * kk + 2),
                    (4 * kk + 2) as f64,
                    f(v),
                    Standing::Established,
                    "exact turns (proven optimal)",
                    FIG5,
                );
                if let Some(c) = cover {
                    opt_tour_cover = c;
                }
                v
            }
            None => {
                let verdict = if lb > 4 * kk + 2 {
                    "contradicted"
                } else {
                    "upper bound met"
                };
                r.push(
                    "opt_tour_turns",
                    format!("4k + 2 = {}", 4 * kk + 2),
                    Some((4 * kk + 2) as f64),
                    f(spiral.turns),
                    Standing::Established,
                    verdict,
                    &format!("spiral; exact turns hit the time limit with lower bound {lb}"),
                    FIG5,
                );
                spiral.turns
            }
        }
    } else {
        r.push(
            "opt_tour_turns",
            format!("4k + 2 = {}", 4 * kk + 2),
            Some((4 * kk + 2) as f64),
            f(spiral.turns),
            Standing::Established,
            "upper bound met",
            &format!(
                "spiral (upper bound); exact turns not run (k > {})",
                opts.donut_exact_k
            ),
            FIG5,
        );
        spiral.turns
    };
    // The algorithm: strips-matching, its cycle cover and both merges.
    let (_, cc) = run_algorithm(
        &region,
        "strips-matching",
        Merge::Smart,
        AlgoObjective::CcTurns,
    )?;
    r.claim(
        "strips_matching_cc_turns",
        format!("8k + 2 = {}", 8 * kk + 2),
        (8 * kk + 2) as f64,
        f(cc.turns),
        Standing::Example,
        "strips-matching cycle cover (checker)",
        FIG5,
    );
    r.claim(
        "strips_matching_cc_cycles",
        format!("2k = {}", 2 * kk),
        (2 * kk) as f64,
        Some(cc.cycles as f64),
        Standing::Example,
        "strips-matching cycle cover (checker)",
        FIG5,
    );
    let (naive_cover, naive) = run_algorithm(
        &region,
        "strips-matching",
        Merge::Naive,
        AlgoObjective::Turns,
    )?;
    let (_, smart) = run_algorithm(
        &region,
        "strips-matching",
        Merge::Smart,
        AlgoObjective::Turns,
    )?;
    r.claim(
        "naive_tour_turns",
        format!("12k = {}", 12 * kk),
        (12 * kk) as f64,
        f(naive.turns),
        Standing::Example,
        "strips-matching --merge naive (checker)",
        FIG5,
    );
    // Theorem 5.6 on the naive tour: no more turns, coverage at most 4.
    if naive.length <= opts.coverage4_max_length {
        let (rewritten, stuck) = crate::algorithms::coverage4::coverage4(&region, &naive_cover);
        let c4 = checked(&region, &rewritten, "coverage4 of the naive tour")?;
        r.claim_at_most(
            "coverage4_turns",
            format!("at most the naive tour's {}", naive.turns),
            naive.turns as f64,
            f(c4.turns),
            &format!(
                "--coverage4 on the naive tour (max coverage {} before)",
                naive.max_coverage
            ),
            "turn-cost paper, Theorem 5.6",
        );
        let reached = c4.max_coverage <= 4;
        r.push(
            "coverage4_max_coverage",
            "at most 4".to_string(),
            Some(4.0),
            Some(f64::from(c4.max_coverage)),
            Standing::Construction,
            if reached { "holds" } else { "not reached" },
            &format!("--coverage4 on the naive tour (checker; {stuck} pixels left above 4)"),
            "turn-cost paper, Theorem 5.6",
        );
    }
    let worst = cc.turns + 2 * (cc.cycles as u64).saturating_sub(1);
    r.report(
        "crossing_merge_turns",
        "t + 2(c - 1): every merge at a crossing (+2)".to_string(),
        f(worst),
        "from the strips-matching cycle cover (Theorem 4.2 with +2 per merge)",
        FIG5,
    );
    r.report(
        "smart_tour_turns",
        "what smart merging achieves".to_string(),
        f(smart.turns),
        "strips-matching --merge smart (checker)",
        FIG5,
    );
    r.report(
        "ratio_cc",
        "cycle cover / optimal cycle cover -> 2".to_string(),
        ratio(cc.turns, rings.turns),
        "strips_matching_cc_turns / rings_cc_turns",
        FIG5,
    );
    r.report(
        "ratio_naive",
        "naive tour / optimal tour -> 3".to_string(),
        ratio(naive.turns, opt_tour),
        "naive_tour_turns / opt_tour_turns",
        FIG5,
    );
    r.report(
        "ratio_crossing",
        "crossing merges / optimal tour -> 3".to_string(),
        ratio(worst, opt_tour),
        "crossing_merge_turns / opt_tour_turns",
        FIG5,
    );
    r.report(
        "ratio_smart",
        "smart tour / optimal tour".to_string(),
        ratio(smart.turns, opt_tour),
        "smart_tour_turns / opt_tour_turns",
        FIG5,
    );
    let rows = r.rows;
    Ok(Member {
        family: "donut",
        member,
        param: kk,
        region,
        rows,
        drawings: vec![
            (
                format!("strips-matching, naive merge: {} turns", naive.turns),
                naive_cover,
            ),
            (format!("optimal tour: {opt_tour} turns"), opt_tour_cover),
        ],
    })
}
