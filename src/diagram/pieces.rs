//! Which input segments each built segment came from, when the builder
//! split crossings (`Builder::split_crossings`): both directions of the
//! map, each as one flat array with offsets.

/// The pieces of a split input and the input segments they came from.
#[derive(Clone, Debug, Default)]
pub(crate) struct SplitPieces {
    /// Piece `p` came from `inputs[inputs_start[p]..inputs_start[p + 1]]`
    /// (sorted input segment indices).
    inputs_start: Vec<u32>,
    inputs: Vec<u32>,
    /// Input segment `i` became `pieces[pieces_start[i]..pieces_start[i + 1]]`
    /// (sorted piece indices; none when it shrank to a point).
    pieces_start: Vec<u32>,
    pieces: Vec<u32>,
    /// The largest distance from a piece to an input segment it came from.
    pub(crate) max_displacement: f64,
    /// The side of the snapping pixels, in input units.
    pub(crate) pixel: f64,
}

impl SplitPieces {
    /// The map from each piece's input segments (`origins[p]`, sorted) for
    /// `input_segments` input segments.
    pub(crate) fn new(origins: &[Vec<u32>], input_segments: usize, max_displacement: f64, pixel: f64) -> SplitPieces {
        let mut inputs_start = Vec::with_capacity(origins.len() + 1);
        let mut inputs = Vec::new();
        let mut count = vec![0u32; input_segments + 1];
        inputs_start.push(0);
        for list in origins {
            inputs.extend_from_slice(list);
            inputs_start.push(inputs.len() as u32);
            for &i in list {
                count[i as usize + 1] += 1;
            }
        }
        for i in 0..input_segments {
            count[i + 1] += count[i];
        }
        let pieces_start = count.clone();
        let mut pieces = vec![0u32; inputs.len()];
        for (p, list) in origins.iter().enumerate() {
            for &i in list {
                pieces[count[i as usize] as usize] = p as u32;
                count[i as usize] += 1;
            }
        }
        SplitPieces { inputs_start, inputs, pieces_start, pieces, max_displacement, pixel }
    }

    /// The input segments piece `p` came from; empty out of range.
    pub(crate) fn inputs_of(&self, p: usize) -> &[u32] {
        range(&self.inputs_start, &self.inputs, p)
    }

    /// The pieces input segment `i` became; empty out of range.
    pub(crate) fn pieces_of(&self, i: usize) -> &[u32] {
        range(&self.pieces_start, &self.pieces, i)
    }

    pub(crate) fn piece_count(&self) -> usize {
        self.inputs_start.len() - 1
    }
}

fn range<'a>(start: &[u32], items: &'a [u32], k: usize) -> &'a [u32] {
    match (start.get(k), start.get(k + 1)) {
        (Some(&from), Some(&to)) => &items[from as usize..to as usize],
        _ => &[],
    }
}
