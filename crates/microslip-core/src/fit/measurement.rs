//! What a fit is given: measured (load, response) points, with an optional standard deviation
//! of each response. Reading them from a file is the application's job (`measured` there).

/// Fewest rows a fit accepts: two parameters need at least one more point than parameters.
pub const MIN_ROWS: usize = 3;

/// One measurement: the load (N) and the response (mm) of a load-driven structure, whatever it
/// is (the beams' tip deflection w(L) under the tip force, the lap joint's displacement Delta
/// under the force through it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measurement {
    /// The load: tip force on each beam, or the force through the joint (N).
    pub force: f64,
    /// The response to the load: the displacement the structure's curve plots against it (mm).
    pub response: f64,
}

/// A measured curve and, when the file has a `sigma_mm` column, the standard deviation of each
/// response (mm), for [`super::Weights::Sigma`].
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The measurements, in file order.
    pub points: Vec<Measurement>,
    /// One standard deviation (mm, > 0) per measurement, or None without the column.
    pub sigma: Option<Vec<f64>>,
}
