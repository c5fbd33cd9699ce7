//! Setting the flow's fields from numpy arrays (issue 32): the face velocities and the water
//! fraction, in the shapes their getters return (`sim.rs`). The pressure stays read only: the
//! next step's projection sets it.

use numpy::{PyReadonlyArray3, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use riprap::fluid::Fluid;

/// The array's values in (k, j, i) order after checking its shape against `n` = [nx, ny, nz]
/// and that every value is finite.
fn values(a: &PyReadonlyArray3<'_, f64>, n: [usize; 3], what: &str) -> PyResult<Vec<f64>> {
    let want = [n[2], n[1], n[0]];
    if a.shape() != want {
        return Err(PyValueError::new_err(format!(
            "{what}: shape {:?}, expected {want:?} (nz, ny, nx)",
            a.shape()
        )));
    }
    let v: Vec<f64> = a.as_array().iter().copied().collect();
    if let Some(q) = v.iter().position(|x| !x.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "{what}: value {q} is not finite"
        )));
    }
    Ok(v)
}

/// Replaces the face velocities (u, v, w) [m/s]: u of shape (nz, ny, nx + 1), v (nz, ny + 1,
/// nx), w (nz + 1, ny, nx), as `flow_velocity` gives them; the ghosts then follow the
/// boundaries. The field is not projected: the next step's projection makes it
/// divergence-free.
pub fn set_velocity(f: &mut Fluid, uvw: &[PyReadonlyArray3<'_, f64>]) -> PyResult<()> {
    if uvw.len() != 3 {
        return Err(PyValueError::new_err(format!(
            "flow_velocity: {} arrays, expected three (u, v, w)",
            uvw.len()
        )));
    }
    let g = *f.grid();
    let mut state = f.state().clone();
    for (a, arr) in uvw.iter().enumerate() {
        let mut n = g.n;
        n[a] += 1;
        let v = values(
            arr,
            n,
            ["flow_velocity u", "flow_velocity v", "flow_velocity w"][a],
        )?;
        let mut q = 0;
        for k in 0..n[2] {
            for j in 0..n[1] {
                let c = g.cell(0, j, k);
                state.velocity[a][c..c + n[0]].copy_from_slice(&v[q..q + n[0]]);
                q += n[0];
            }
        }
    }
    f.restore(state).map_err(PyValueError::new_err)?;
    f.fill_ghosts();
    Ok(())
}

/// Replaces the water fraction α of every cell, (nz, ny, nx), each within [0, 1]; ρ̄ follows
/// from it and the pressure is reset to the hydrostatic one of the new water
/// (`Fluid::set_water_fraction`). With coupled solids their share of ρ̄ returns at the next
/// step's correction.
pub fn set_water_fraction(f: &mut Fluid, a: &PyReadonlyArray3<'_, f64>) -> PyResult<()> {
    let g = *f.grid();
    let v = values(a, g.n, "water_fraction")?;
    if let Some(q) = v.iter().position(|x| !(0.0..=1.0).contains(x)) {
        return Err(PyValueError::new_err(format!(
            "water_fraction: value {q} is {}, outside [0, 1]",
            v[q]
        )));
    }
    let (o, h) = (g.origin.to_array(), g.spacing.to_array());
    let [nx, ny, _] = g.n;
    f.set_water_fraction(|lo, _| {
        // The cell whose low corner is `lo`.
        let [i, j, k] = std::array::from_fn(|d| ((lo[d] - o[d]) / h[d]).round() as usize);
        v[(k * ny + j) * nx + i]
    })
    .map_err(|e| PyValueError::new_err(format!("water_fraction: {e}")))
}
