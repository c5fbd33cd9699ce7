//! Blocks changed between steps from Python (issue 32): added from a template, removed with
//! their members, moved in place. The `Simulation` methods in `sim.rs` call these and then
//! rebuild the neighbour lists.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use riprap::math::{Quat, Vec3};
use riprap::rigid::blocks::RigidState;
use riprap::scenario::Source;
use riprap::simulation::Simulation;

use crate::sim::vec3;

/// Adds a block of the template named `template`, placed as a `[[blocks]]` list entry places
/// one: `motion` = [centre [m], rotation (axis × angle [rad]) from the template's principal
/// axes, velocity [m/s], angular velocity [rad/s]]. Returns its id.
pub fn add(
    sim: &mut Simulation,
    src: &Source,
    template: &str,
    motion: [[f64; 3]; 4],
) -> PyResult<u32> {
    let [position, rotation, velocity, angular_velocity] = motion;
    let rigid = &sim.rigid;
    let Some(t) = rigid.templates.iter().position(|t| t.name == template) else {
        let names: Vec<&str> = rigid.templates.iter().map(|t| t.name.as_str()).collect();
        return Err(PyValueError::new_err(format!(
            "add_block: no block template named `{template}` (the scenario has {names:?})"
        )));
    };
    let section = (src.scenario.block_templates.iter())
        .find(|s| s.name == template)
        .expect("the templates are the scenario's");
    let d = &sim.dem;
    let m = d
        .material_index(&section.material)
        .expect("the scenario's checks found the material");
    let tpl = &rigid.templates[t];
    let state = RigidState {
        centre: vec3(position, "add_block: position")?,
        velocity: vec3(velocity, "add_block: velocity")?,
        orientation: Quat::from_scaled_axis(vec3(rotation, "add_block: rotation")?)
            * tpl.principal_axes,
        angular_velocity: vec3(angular_velocity, "add_block: angular_velocity")?,
    };
    if let Some(x) = (tpl.member_positions(state.centre, state.orientation).iter())
        .find(|x| !d.domain.contains(**x))
    {
        return Err(PyValueError::new_err(format!(
            "add_block: a member sphere of the block lies outside the domain, at {:?}",
            x.to_array()
        )));
    }
    let (density, gravity) = (d.materials[m as usize].density, d.gravity);
    let s = &mut sim.dem.spheres;
    let first = s.len();
    let id = sim.rigid.add_block(s, t, m, density, state);
    // The members' weight, as fed spheres get, for the next step's opening half kick.
    for i in first..s.len() {
        s.force[i] = s.mass[i] * gravity;
    }
    Ok(id)
}

/// Removes the blocks `ids` with their members, and the wires and bonds attached to them
/// (`RigidBodies::remove_links_to`: the other links keep their order). Returns how many
/// blocks went.
pub fn remove(sim: &mut Simulation, ids: &[u32]) -> PyResult<usize> {
    let rigid = &mut sim.rigid;
    let s = &sim.dem.spheres;
    let mut keep = vec![true; s.len()];
    let mut members = Vec::new();
    for &id in ids {
        let Some(b) = rigid.blocks.slot_of(id) else {
            return Err(PyValueError::new_err(format!(
                "remove_blocks: no block {id}"
            )));
        };
        for m in rigid.blocks.member_ids(b) {
            members.push(*m);
            if let Some(k) = s.slot_of(*m) {
                keep[k] = false;
            }
        }
    }
    rigid.remove_links_to(ids, &members);
    let removed = rigid.drop_partial_blocks(s, &mut keep);
    sim.dem.spheres.retain(&keep);
    Ok(removed)
}

/// Moves block `id` to centre `position` [m], and to `orientation` (x, y, z, w), normalised
/// here, and `motion` = (velocity [m/s], angular velocity [rad/s]) where given; its members
/// go into the rigid shape at the new pose with the block's velocity field.
pub fn set_pose(
    sim: &mut Simulation,
    id: u32,
    position: [f64; 3],
    orientation: Option<[f64; 4]>,
    motion: (Option<[f64; 3]>, Option<[f64; 3]>),
) -> PyResult<()> {
    let blocks = &sim.rigid.blocks;
    let Some(b) = blocks.slot_of(id) else {
        return Err(PyValueError::new_err(format!(
            "set_block_pose: no block {id}"
        )));
    };
    let mut st = blocks.state(b);
    st.centre = vec3(position, "set_block_pose: position")?;
    if let Some(q) = orientation {
        let q = Quat::from_array(q);
        if !(q.is_finite() && q.length() > 0.0) {
            return Err(PyValueError::new_err(format!(
                "set_block_pose: orientation {:?} is not a rotation",
                q.to_array()
            )));
        }
        st.orientation = q.normalize();
    }
    if let Some(v) = motion.0 {
        st.velocity = vec3(v, "set_block_pose: velocity")?;
    }
    if let Some(w) = motion.1 {
        st.angular_velocity = vec3(w, "set_block_pose: angular_velocity")?;
    }
    let domain = sim.dem.domain;
    let arms: Vec<Vec3> = (blocks.member_offsets(b).iter())
        .map(|&q| st.orientation * q)
        .collect();
    if let Some(r) = arms.iter().find(|&&r| !domain.contains(st.centre + r)) {
        return Err(PyValueError::new_err(format!(
            "set_block_pose: a member sphere would lie outside the domain, at {:?}",
            (st.centre + *r).to_array()
        )));
    }
    let ids = blocks.member_ids(b).to_vec();
    let s = &mut sim.dem.spheres;
    for (sid, r) in ids.into_iter().zip(arms) {
        let i = s.slot_of(sid).expect("a block's members are present");
        s.position[i] = domain.wrap(st.centre + r);
        s.velocity[i] = st.velocity + st.angular_velocity.cross(r);
        s.angular_velocity[i] = st.angular_velocity;
    }
    sim.rigid.blocks.set_state(b, st);
    Ok(())
}
