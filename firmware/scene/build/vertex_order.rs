//! Spot's triangles put in an order that reuses the vertex cache, and its vertices numbered in the order that
//! first uses them.
//!
//! The core's vertex cache (`core/src/pipeline/vertex_cache.rs`: 32 entries, each vertex in the slot its
//! index hashes to) keeps a vertex's transformed position while the triangles after it use it again. The file's
//! order sends each triangle through 1.31 position runs of the vertex stage; this order, 0.72 (counted through the
//! core's own draw by `tests/tests/firmware_checksum.rs`). The order is greedy, as in Forsyth,
//! "Linear-speed vertex cache optimisation" (2006): the next triangle is the one whose vertices score highest,
//! a vertex scoring for being recent in a simulated least-recently-used cache of the core's size and for having few
//! triangles left (so that none is stranded); numbering the vertices by first use then places the ones used
//! together in different slots of the hashed cache (without it, 0.83 runs a triangle in a model of the cache that
//! gives the two figures above exactly). Only square roots and the four basic operations enter the
//! scores, so every build machine computes the same order.

/// Entries of the simulated cache: the core's vertex cache size.
const CACHE_SIZE: usize = 32;
/// The score of the three vertices of the triangle just emitted: less than the next ones, so that a triangle
/// sharing an edge with the last is not always preferred to one completing a fan (Forsyth's value).
const LAST_TRIANGLE_SCORE: f64 = 0.75;
/// The bonus for a vertex with few triangles left: `VALENCE_BOOST_SCALE / sqrt(triangles left)`.
const VALENCE_BOOST_SCALE: f64 = 2.0;

/// A mesh's indices in the new order, and for each new vertex number the old one.
pub struct VertexOrder {
    /// Three new vertex numbers per triangle; each triangle's corners in their old order (winding and first vertex
    /// kept).
    pub indices: Vec<u32>,
    /// `old_vertex[new]`: the old number of each new vertex. Vertices no triangle uses come last, in their old
    /// order.
    pub old_vertex: Vec<u32>,
}

/// The order for `indices` (three per triangle) over `vertex_count` vertices.
pub fn optimise(indices: &[u32], vertex_count: usize) -> VertexOrder {
    let triangles: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let mut triangles_of: Vec<Vec<usize>> = vec![Vec::new(); vertex_count];
    for (t, corners) in triangles.iter().enumerate() {
        for &v in corners {
            triangles_of[v as usize].push(t);
        }
    }
    let mut cache_position: Vec<Option<usize>> = vec![None; vertex_count];
    let score = |left: usize, position: Option<usize>| -> f64 {
        if left == 0 {
            return -1.0;
        }
        let recent = match position {
            None => 0.0,
            Some(p) if p < 3 => LAST_TRIANGLE_SCORE,
            // (1 - (p - 3) / (size - 3))^1.5, Forsyth's decay, as x * sqrt(x).
            Some(p) => {
                let x = 1.0 - (p - 3) as f64 / (CACHE_SIZE - 3) as f64;
                x * x.sqrt()
            }
        };
        recent + VALENCE_BOOST_SCALE / (left as f64).sqrt()
    };
    let mut vertex_score: Vec<f64> = triangles_of.iter().map(|t| score(t.len(), None)).collect();
    let triangle_score = |vertex_score: &[f64], t: &[u32; 3]| t.iter().map(|&v| vertex_score[v as usize]).sum::<f64>();
    let mut scores: Vec<f64> = triangles.iter().map(|t| triangle_score(&vertex_score, t)).collect();
    let mut emitted = vec![false; triangles.len()];
    let mut cache: Vec<u32> = Vec::with_capacity(CACHE_SIZE + 3);
    let mut order = Vec::with_capacity(triangles.len());
    // The best triangle not yet emitted, lowest index on ties: where no cached vertex has triangles left.
    let best_of_all = |scores: &[f64], emitted: &[bool]| {
        (0..triangles.len()).filter(|&t| !emitted[t]).fold(None, |best: Option<usize>, t| match best {
            Some(b) if scores[b] >= scores[t] => Some(b),
            _ => Some(t),
        })
    };
    let mut next = best_of_all(&scores, &emitted);
    while let Some(t) = next {
        emitted[t] = true;
        order.push(t);
        let corners = triangles[t];
        for &v in &corners {
            let list = &mut triangles_of[v as usize];
            let at = list.iter().position(|&u| u == t).expect("a triangle is listed by its vertices");
            list.swap_remove(at);
        }
        // The triangle's vertices to the front, the rest after them in their order; past the size, evicted.
        cache.retain(|v| !corners.contains(v));
        cache.splice(0..0, corners);
        let evicted = cache.split_off(cache.len().min(CACHE_SIZE));
        for &v in &evicted {
            cache_position[v as usize] = None;
        }
        for (p, &v) in cache.iter().enumerate() {
            cache_position[v as usize] = Some(p);
        }
        for &v in cache.iter().chain(&evicted) {
            vertex_score[v as usize] = score(triangles_of[v as usize].len(), cache_position[v as usize]);
        }
        for &v in cache.iter().chain(&evicted) {
            for &u in &triangles_of[v as usize] {
                scores[u] = triangle_score(&vertex_score, &triangles[u]);
            }
        }
        next = None;
        for &v in &cache {
            for &u in &triangles_of[v as usize] {
                if next.is_none_or(|b| scores[u] > scores[b] || (scores[u] == scores[b] && u < b)) {
                    next = Some(u);
                }
            }
        }
        if next.is_none() {
            next = best_of_all(&scores, &emitted);
        }
    }

    let mut new_vertex: Vec<Option<u32>> = vec![None; vertex_count];
    let mut old_vertex = Vec::with_capacity(vertex_count);
    let mut number = |v: u32, old_vertex: &mut Vec<u32>| {
        *new_vertex[v as usize].get_or_insert_with(|| {
            old_vertex.push(v);
            (old_vertex.len() - 1) as u32
        })
    };
    let mut reordered = Vec::with_capacity(indices.len());
    for &t in &order {
        for v in triangles[t] {
            reordered.push(number(v, &mut old_vertex));
        }
    }
    for v in 0..vertex_count as u32 {
        number(v, &mut old_vertex);
    }
    VertexOrder { indices: reordered, old_vertex }
}
