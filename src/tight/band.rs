//! The band B_k: the 6/5 bound of Theorem 5 of the milling paper, met by `tsp65`.

use super::*;

/// All measurements of the band B_k.
pub fn band(k: usize, opts: &TightOptions) -> Result<Member> {
    let region = family_region(&GenParams {
        k: Some(k),
        ..GenParams::new(Family::Band, 0)
    })?;
    let member = format!("k={k}");
    let kk = k as u64;
    let n = region.len() as u64;
    let mut r = Rows {
        family: "band",
        member: &member,
        param: kk,
        n,
        rows: Vec::new(),
    };
    let bound = (6 * n - 4) / 5;
    r.claim(
        "n",
        format!("5k + 4 = {}", 5 * kk + 4),
        (5 * kk + 4) as f64,
        f(n),
        Standing::Established,
        "pixel count",
        FIG16,
    );
    let (black, _) = crate::topology::colour_counts(&region);
    r.claim(
        "black_pixels",
        format!("3k + 2 = {}", 3 * kk + 2),
        (3 * kk + 2) as f64,
        f(black as u64),
        Standing::Established,
        "pixels with x + y even",
        FIG16,
    );
    let (tour, tsp) = run_algorithm(&region, "tsp65", Merge::Smart, AlgoObjective::Length)?;
    r.claim(
        "tsp65_length",
        format!("(6N - 4)/5 = {bound}"),
        bound as f64,
        f(tsp.length),
        Standing::Established,
        "tsp65 (checker)",
        FIG16,
    );
    // Every closed walk alternates colours, so it has length ≥ 2·#black: when tsp65 meets
    // that bound, it is optimal whatever the exact solver says.
    let colour_bound = 2 * black as u64;
    let mut opt_cover = tour.clone();
    let (opt, how) = if k <= opts.band_exact_k {
        let (value, lb, cover) = exact_solve(&region, ExactObjective::Length, opts.time_limit);
        if let Some(c) = cover.filter(|_| value.is_some()) {
            opt_cover = c;
        }
        match value {
            Some(v) => (Some(v), "exact length (proven optimal)".to_string()),
            None => (
                (tsp.length == colour_bound).then_some(tsp.length),
                format!("tsp65 = 2 #black (exact hit the time limit, bound {lb})"),
            ),
        }
    } else {
        (
            (tsp.length == colour_bound).then_some(tsp.length),
            "tsp65 meets the colour bound 2 #black (proven optimal)".to_string(),
        )
    };
    r.claim(
        "opt_length",
        format!("(6N - 4)/5 = {bound}"),
        bound as f64,
        opt.map(|v| v as f64),
        Standing::Established,
        &how,
        FIG16,
    );
    r.report(
        "ratio_opt_n",
        "OPT / N -> 6/5".to_string(),
        opt.and_then(|v| ratio(v, n)),
        "opt_length / n",
        FIG16,
    );
    r.report(
        "ratio_tsp65_opt",
        "tsp65 / OPT (Corollary 3: <= 6/5)".to_string(),
        opt.and_then(|v| ratio(tsp.length, v)),
        "tsp65_length / opt_length",
        FIG16,
    );
    let rows = r.rows;
    Ok(Member {
        family: "band",
        member,
        param: kk,
        region,
        rows,
        drawings: vec![
            (format!("tsp65: length {}", tsp.length), tour),
            (
                format!("optimal tour: length {}", opt.unwrap_or(tsp.length)),
                opt_cover,
            ),
        ],
    })
}
