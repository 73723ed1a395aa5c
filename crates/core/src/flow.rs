//! Maximum flow and minimum cuts on small undirected graphs with real capacities (Dinic's
//! algorithm), for the Gomory–Hu trees of the exact models' connectivity cuts
//! (`mowmill_exact`) and of the matching LP's odd-set cuts
//! (`mowmill::algorithms::matching`).

/// Maximum flow by Dinic's algorithm on an undirected graph with real capacities.
pub struct FlowGraph {
    n: usize,
    head: Vec<usize>,
    /// Arc k: to[k], cap[k]; arc k ^ 1 is its reverse.
    to: Vec<u32>,
    next: Vec<usize>,
    cap: Vec<f64>,
    base: Vec<f64>,
}

const NIL: usize = usize::MAX;

impl FlowGraph {
    pub fn new(n: usize, edges: &[(usize, usize, f64)]) -> FlowGraph {
        let mut g = FlowGraph {
            n,
            head: vec![NIL; n],
            to: Vec::with_capacity(2 * edges.len()),
            next: Vec::with_capacity(2 * edges.len()),
            cap: Vec::with_capacity(2 * edges.len()),
            base: Vec::with_capacity(2 * edges.len()),
        };
        for &(a, b, c) in edges {
            for (u, v) in [(a, b), (b, a)] {
                g.to.push(v as u32);
                g.next.push(g.head[u]);
                g.head[u] = g.to.len() - 1;
                g.base.push(c);
            }
        }
        g.cap = g.base.clone();
        g
    }

    /// Max flow from `s` to `t` (stops once it reaches `stop_at`); the source side of a minimum
    /// cut is left in `side`.
    pub fn max_flow(&mut self, s: usize, t: usize, stop_at: f64, side: &mut [bool]) -> f64 {
        const EPS: f64 = 1e-9;
        self.cap.copy_from_slice(&self.base);
        let mut flow = 0.0;
        let mut level = vec![u32::MAX; self.n];
        let mut it = vec![NIL; self.n];
        let mut queue = Vec::with_capacity(self.n);
        loop {
            level.iter_mut().for_each(|l| *l = u32::MAX);
            level[s] = 0;
            queue.clear();
            queue.push(s);
            let mut h = 0;
            while h < queue.len() {
                let u = queue[h];
                h += 1;
                let mut k = self.head[u];
                while k != NIL {
                    let v = self.to[k] as usize;
                    if self.cap[k] > EPS && level[v] == u32::MAX {
                        level[v] = level[u] + 1;
                        queue.push(v);
                    }
                    k = self.next[k];
                }
            }
            if level[t] == u32::MAX || flow >= stop_at {
                for v in 0..self.n {
                    side[v] = level[v] != u32::MAX;
                }
                return flow;
            }
            it.copy_from_slice(&self.head);
            loop {
                let f = self.augment(s, t, &level, &mut it);
                if f <= EPS {
                    break;
                }
                flow += f;
            }
        }
    }

    /// One augmenting path in the level graph (iterative DFS); returns its bottleneck.
    fn augment(&mut self, s: usize, t: usize, level: &[u32], it: &mut [usize]) -> f64 {
        const EPS: f64 = 1e-9;
        let mut path: Vec<usize> = Vec::new();
        let mut u = s;
        loop {
            if u == t {
                let f = path
                    .iter()
                    .map(|&k| self.cap[k])
                    .fold(f64::INFINITY, f64::min);
                for &k in &path {
                    self.cap[k] -= f;
                    self.cap[k ^ 1] += f;
                }
                return f;
            }
            let mut advanced = false;
            while it[u] != NIL {
                let k = it[u];
                let v = self.to[k] as usize;
                if self.cap[k] > EPS && level[v] == level[u] + 1 {
                    path.push(k);
                    u = v;
                    advanced = true;
                    break;
                }
                it[u] = self.next[k];
            }
            if !advanced {
                // Dead end: retreat and skip the arc that led here.
                let Some(k) = path.pop() else { return 0.0 };
                u = self.to[k ^ 1] as usize;
                it[u] = self.next[it[u]];
            }
        }
    }
}
