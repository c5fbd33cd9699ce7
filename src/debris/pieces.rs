//! [`Debris`]: the pieces as rigid blocks, their member spheres in a DEM for the contacts, and
//! the sub-steps of the module docs.

use serde::{Deserialize, Serialize};

use super::load::{balance, drag_factor, flooded_mass, sinking_time, slide, Phase};
use super::shape::BoxShape;
use super::{FlowField, Parameters};
use crate::dem::contacts::SavedContact;
use crate::dem::domain::Domain;
use crate::dem::forces::{compute_forces, start_forces};
use crate::dem::material::{ContactModel, HookeOptions, Material};
use crate::dem::neighbor::DEFAULT_SKIN_FRACTION;
use crate::dem::spheres::{NewSphere, Spheres};
use crate::dem::wall_contacts::SavedWallContacts;
use crate::dem::walls::{Motion, Shape, Wall};
use crate::dem::Dem;
use crate::geometry::{Cuboid, TriMesh};
use crate::math::{Quat, Vec3};
use crate::rigid::blocks::{Blocks, RigidState};
use crate::rigid::newton_euler::drift;

/// A structure the pieces collide with, standing through their contact plane: a rectangle
/// (a DEM box) or a polygon (a DEM triangle mesh of its vertical side faces, a prism).
#[derive(Clone, Debug, PartialEq)]
pub enum Structure {
    /// A rectangle: (x, y) of its lower-left and upper-right corners [m].
    Box([f64; 2], [f64; 2]),
    /// A polygon: its vertices (x, y) [m] in either order, at least three, not crossing
    /// itself (the caller checks).
    Polygon(Vec<[f64; 2]>),
}

impl Structure {
    /// The DEM wall of this structure, reaching `reach` [m] above and below the contact plane.
    fn wall(&self, name: String, reach: f64) -> Result<Wall, String> {
        let shape = match self {
            Structure::Box(lo, hi) => Shape::Cuboid(Cuboid {
                min: Vec3::new(lo[0], lo[1], -reach),
                max: Vec3::new(hi[0], hi[1], reach),
                inside: false,
            }),
            Structure::Polygon(v) => {
                Shape::Mesh(prism(v, reach).map_err(|e| format!("{name}: {e}"))?)
            }
        };
        Ok(Wall {
            name,
            shape,
            material: 0,
            motion: Motion::Fixed,
        })
    }
}

/// The side faces of the vertical prism over `polygon` from z = −`reach` to `reach` [m]: two
/// triangles per edge. The DEM's meshes are two-sided, so the order of the vertices does not
/// matter; the ends are left open (the pieces move in the plane z = 0 and meet only the
/// sides).
fn prism(polygon: &[[f64; 2]], reach: f64) -> Result<TriMesh, String> {
    let n = polygon.len();
    if n < 3 {
        return Err(format!("a polygon needs 3 vertices, not {n}"));
    }
    let mut vertices = Vec::with_capacity(2 * n);
    for v in polygon {
        vertices.push(Vec3::new(v[0], v[1], -reach));
        vertices.push(Vec3::new(v[0], v[1], reach));
    }
    let mut triangles = Vec::with_capacity(2 * n);
    for k in 0..n {
        let (a, b) = (2 * k as u32, 2 * ((k + 1) % n) as u32);
        triangles.push([a, b, b + 1]);
        triangles.push([a, b + 1, a + 1]);
    }
    TriMesh::new(vertices, triangles).map_err(|e| e.to_string())
}

/// Sub-steps per contact period π √(m*/k) [-].
pub const STEPS_PER_CONTACT: f64 = 20.0;

/// One piece of debris as the scenario places it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Piece {
    /// Name in messages and outputs.
    pub name: String,
    /// The box.
    pub shape: BoxShape,
    /// Dry mass M₀ [kg].
    pub mass: f64,
    /// Fraction φ of the volume that flooding can fill [-].
    pub floodable_fraction: f64,
    /// Flooding time constant τ [s] (∞: watertight).
    pub flooding_time: f64,
    /// Centre (x, y) at the start [m].
    pub position: [f64; 2],
    /// Heading of the long axis, anticlockwise from x [rad].
    pub heading: f64,
}

/// What evolves of a piece beside its rigid state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PieceState {
    /// Time it has floated [s].
    pub floated: f64,
    /// Where it stands.
    pub phase: Phase,
    /// Held by static friction.
    pub stuck: bool,
    /// Wet height w of the last sub-step [m] (the draft afloat).
    pub wet_height: f64,
    /// Bed reaction N of the last sub-step [N].
    pub normal: f64,
}

/// All a run needs to continue the debris bit for bit.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DebrisState {
    /// Simulated time [s].
    pub time: f64,
    /// Sub-steps taken.
    pub steps: u64,
    /// The blocks.
    pub blocks: Blocks,
    /// The pieces' phases.
    pub pieces: Vec<PieceState>,
    /// The member spheres, in storage order.
    pub spheres: Spheres,
    /// Positions at the last neighbour build, by slot [m].
    pub reference: Vec<Vec3>,
    /// Time of the last neighbour build [s].
    pub built_at: f64,
    /// Pair contact history.
    pub contacts: Vec<SavedContact>,
    /// Wall contact history.
    pub walls: Vec<SavedWallContacts>,
}

/// What `riprap check` says of a piece in the initial flow.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// Name.
    pub name: String,
    /// Mass [kg].
    pub mass: f64,
    /// Free draft M/(ρA) [m].
    pub free_draft: f64,
    /// Local depth at the centre [m] (`None`: outside the flow).
    pub depth: Option<f64>,
    /// Wet height w [m].
    pub wet_height: f64,
    /// Wetted frontal area end-on, B w [m²].
    pub area_end_on: f64,
    /// Wetted frontal area broadside, L w [m²].
    pub area_broadside: f64,
    /// Phase at the start.
    pub phase: Phase,
    /// Floating time after which it sinks [s] (`None`: never).
    pub sinks_after: Option<f64>,
    /// Members in the contacts.
    pub spheres: usize,
}

/// The debris of a run.
#[derive(Clone, Debug)]
pub struct Debris {
    params: Parameters,
    pieces: Vec<Piece>,
    blocks: Blocks,
    state: Vec<PieceState>,
    dem: Dem,
    /// Storage slot of each member, aligned with `blocks.member_id`.
    slots: Vec<u32>,
    /// Contact force (x, y) and yaw torque per block, of the current sub-step [N], [N m].
    wrench: Vec<[f64; 3]>,
    dt_max: f64,
    time: f64,
    steps: u64,
}

fn invalid(p: &Piece) -> Option<String> {
    let s = &p.shape;
    for (k, v) in [
        ("length", s.length),
        ("width", s.width),
        ("height", s.height),
        ("mass", p.mass),
    ] {
        if !(v > 0.0 && v.is_finite()) {
            return Some(format!("{}: {k} {v} must be a positive number", p.name));
        }
    }
    if s.width > s.length {
        return Some(format!(
            "{}: the width {} m exceeds the length {} m (the length is the long side)",
            p.name, s.width, s.length
        ));
    }
    if !(0.0..=1.0).contains(&p.floodable_fraction) {
        return Some(format!(
            "{}: floodable_fraction {} must lie in [0, 1]",
            p.name, p.floodable_fraction
        ));
    }
    if p.flooding_time.is_nan() || p.flooding_time <= 0.0 {
        return Some(format!(
            "{}: flooding_time {} must be positive (or absent: watertight)",
            p.name, p.flooding_time
        ));
    }
    if !(p.position.iter().all(|x| x.is_finite()) && p.heading.is_finite()) {
        return Some(format!(
            "{}: the position and heading must be numbers",
            p.name
        ));
    }
    None
}

impl Debris {
    /// The pieces `pieces` in `flow`, with the `structures` as DEM walls (rectangles as
    /// solid boxes, polygons as the side faces of prisms), in a DEM domain over `extent` (min
    /// and max corners [m]).
    pub fn new(
        params: Parameters,
        pieces: Vec<Piece>,
        structures: &[Structure],
        extent: ([f64; 2], [f64; 2]),
        flow: &impl FlowField,
    ) -> Result<Debris, String> {
        params.check()?;
        if let Some(e) = pieces.iter().find_map(invalid) {
            return Err(e);
        }
        let lightest = pieces.iter().map(|p| p.mass).fold(f64::INFINITY, f64::min);
        let longest = pieces.iter().map(|p| p.shape.length).fold(1.0f64, f64::max);
        let widest = pieces.iter().map(|p| p.shape.width).fold(1.0f64, f64::max);
        // Two of the lightest blocks: m* = M/2. Restitution e of the damped spring: ζ from e.
        let m_star = 0.5 * if lightest.is_finite() { lightest } else { 1.0 };
        let k = params.contact_stiffness;
        let w0 = (k / m_star).sqrt();
        let ln_e = params.contact_restitution.ln();
        let zeta = -ln_e / (std::f64::consts::PI.powi(2) + ln_e * ln_e).sqrt();
        let gamma = 2.0 * zeta * w0;
        let model = ContactModel::HookeHistory(HookeOptions {
            normal_stiffness: k,
            tangential_stiffness: 2.0 / 7.0 * k,
            normal_damping: gamma,
            tangential_damping: 0.5 * gamma,
        });
        let material = Material {
            name: "debris".into(),
            density: 1000.0,
            young_modulus: 2.0e11,
            poisson_ratio: 0.3,
            friction_coefficient: params.contact_friction,
            restitution_coefficient: params.contact_restitution,
        };
        let margin = longest + 2.0 * widest;
        let domain = Domain {
            min: Vec3::new(extent.0[0] - margin, extent.0[1] - margin, -widest),
            max: Vec3::new(extent.1[0] + margin, extent.1[1] + margin, widest),
            periodic: [false; 3],
        };
        let period = std::f64::consts::PI / (w0 * (1.0 - zeta * zeta).sqrt());
        let dt_max = period / STEPS_PER_CONTACT;
        let mut dem = Dem::new(vec![material], model, domain, dt_max);
        dem.gravity = Vec3::ZERO;
        dem.neighbors.skin = DEFAULT_SKIN_FRACTION * widest;
        for (i, s) in structures.iter().enumerate() {
            dem.walls
                .push(s.wall(format!("structure {i}"), 2.0 * widest)?);
        }
        let mut blocks = Blocks::default();
        let mut state = Vec::with_capacity(pieces.len());
        for (b, p) in pieces.iter().enumerate() {
            let sh = p.shape;
            let q = Quat::from_rotation_z(p.heading);
            let r = 0.5 * sh.width;
            let start = blocks.member_id.len() as u32;
            for [x, y] in sh.members() {
                let off = Vec3::new(x, y, 0.0);
                let id = dem.spheres.push(NewSphere {
                    position: Vec3::new(p.position[0], p.position[1], 0.0) + q * off,
                    velocity: Vec3::ZERO,
                    angular_velocity: Vec3::ZERO,
                    radius: r,
                    material: 0,
                    density: 1000.0,
                    fixed: false,
                });
                let s = dem.spheres.slot_of(id).expect("just added");
                dem.spheres.mass[s] = p.mass;
                dem.spheres.inertia[s] = 0.4 * p.mass * r * r;
                dem.spheres.body[s] = b as u32;
                blocks.member_id.push(id);
                blocks.member_offset.push(off);
            }
            blocks.members.push(start..blocks.member_id.len() as u32);
            let sample = flow.sample(p.position[0], p.position[1]);
            let (bal, bottom) = match sample {
                Some(s) => {
                    let bal = balance(
                        p.mass,
                        sh.plan_area(),
                        sh.height,
                        s.depth,
                        params.water_density,
                        params.gravity,
                    );
                    let bottom = if bal.phase == Phase::Floating {
                        s.surface() - bal.wet_height
                    } else {
                        s.bed
                    };
                    (bal, bottom)
                }
                None => {
                    return Err(format!(
                        "{}: its centre ({}, {}) m lies outside the flow or in a structure",
                        p.name, p.position[0], p.position[1]
                    ))
                }
            };
            let centre = Vec3::new(p.position[0], p.position[1], bottom + 0.5 * sh.height);
            blocks.id.push(b as u32);
            blocks.template.push(0);
            blocks.centre.push(centre);
            blocks.velocity.push(Vec3::ZERO);
            blocks.orientation.push(q);
            blocks.angular_velocity.push(Vec3::ZERO);
            blocks.mass.push(p.mass);
            blocks.inertia.push(inertia(&sh, p.mass));
            blocks.force.push(Vec3::ZERO);
            blocks.torque.push(Vec3::ZERO);
            blocks.displacement.push(Vec3::ZERO);
            blocks.initial_orientation.push(q);
            state.push(PieceState {
                floated: 0.0,
                phase: bal.phase,
                stuck: true,
                wet_height: bal.wet_height,
                normal: bal.normal,
            });
        }
        blocks.next_id = pieces.len() as u32;
        let n_members = blocks.member_id.len();
        let mut d = Debris {
            params,
            wrench: vec![[0.0; 3]; pieces.len()],
            pieces,
            blocks,
            state,
            dem,
            slots: vec![0; n_members],
            dt_max,
            time: 0.0,
            steps: 0,
        };
        d.dem.rebuild_lists(0.0);
        d.refresh_slots();
        Ok(d)
    }

    fn refresh_slots(&mut self) {
        let s = &self.dem.spheres;
        for (slot, &id) in self.slots.iter_mut().zip(&self.blocks.member_id) {
            *slot = s.slot_of(id).expect("members are never removed") as u32;
        }
    }

    /// The settings.
    pub fn parameters(&self) -> &Parameters {
        &self.params
    }

    /// The pieces as placed.
    pub fn pieces(&self) -> &[Piece] {
        &self.pieces
    }

    /// The blocks (centre, velocity, orientation, mass of each piece).
    pub fn blocks(&self) -> &Blocks {
        &self.blocks
    }

    /// The phases and flooding of the pieces.
    pub fn states(&self) -> &[PieceState] {
        &self.state
    }

    /// The contacts' DEM (member spheres, structures).
    pub fn dem(&self) -> &Dem {
        &self.dem
    }

    /// Simulated time [s].
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Sub-steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The longest sub-step Δt_d [s].
    pub fn max_step(&self) -> f64 {
        self.dt_max
    }

    /// Heading of piece `b`'s long axis, anticlockwise from x [rad].
    pub fn heading(&self, b: usize) -> f64 {
        let e = self.blocks.orientation[b] * Vec3::X;
        e.y.atan2(e.x)
    }

    /// What `riprap check` prints of each piece, in `flow` at the start.
    pub fn report(&self, flow: &impl FlowField) -> Vec<Report> {
        let p = &self.params;
        self.pieces
            .iter()
            .map(|pc| {
                let sh = pc.shape;
                let depth = flow.sample(pc.position[0], pc.position[1]).map(|s| s.depth);
                let bal = balance(
                    pc.mass,
                    sh.plan_area(),
                    sh.height,
                    depth.unwrap_or(0.0),
                    p.water_density,
                    p.gravity,
                );
                Report {
                    name: pc.name.clone(),
                    mass: pc.mass,
                    free_draft: pc.mass / (p.water_density * sh.plan_area()),
                    depth,
                    wet_height: bal.wet_height,
                    area_end_on: sh.width * bal.wet_height,
                    area_broadside: sh.length * bal.wet_height,
                    phase: bal.phase,
                    sinks_after: sinking_time(
                        pc.mass,
                        sh.volume(),
                        pc.floodable_fraction,
                        pc.flooding_time,
                        p.water_density,
                    ),
                    spheres: sh.members().len(),
                }
            })
            .collect()
    }

    /// Advances the debris by `dt` [s] in `flow` (the flow at the end of its step):
    /// [`Debris::advance_to`] the time `time() + dt`.
    pub fn advance(&mut self, flow: &impl FlowField, dt: f64) -> Result<(), String> {
        self.advance_to(flow, self.time + dt)
    }

    /// Advances the debris to the time `end` [s] (the flow's, which it then holds to the bit)
    /// in `flow`, in ⌈(end − time) / Δt_d⌉ equal sub-steps. Fails if a block's state is no
    /// longer finite.
    pub fn advance_to(&mut self, flow: &impl FlowField, end: f64) -> Result<(), String> {
        let dt = end - self.time;
        if self.pieces.is_empty() || dt <= 0.0 {
            self.time = self.time.max(end);
            return Ok(());
        }
        let n = (dt / self.dt_max).ceil().max(1.0);
        let h = dt / n;
        for _ in 0..n as u64 {
            self.substep(flow, h);
        }
        self.time = end;
        if let Some(b) = (0..self.blocks.len()).find(|&b| {
            let (c, v) = (self.blocks.centre[b], self.blocks.velocity[b]);
            !(c.is_finite() && v.is_finite())
        }) {
            return Err(format!(
                "debris {} has a non-finite position or velocity at t = {:.6} s",
                self.pieces[b].name, self.time
            ));
        }
        Ok(())
    }

    /// One sub-step of `h` [s] (module docs).
    fn substep(&mut self, flow: &impl FlowField, h: f64) {
        let d = &mut self.dem;
        start_forces(&mut d.spheres, Vec3::ZERO);
        compute_forces(d, self.time, None, true);
        let s = &d.spheres;
        for (b, w) in self.wrench.iter_mut().enumerate() {
            let c = self.blocks.centre[b];
            let mut acc = [0.0; 3];
            for k in self.blocks.members[b].clone() {
                let i = self.slots[k as usize] as usize;
                let (x, f) = (s.position[i], s.force[i]);
                acc[0] += f.x;
                acc[1] += f.y;
                acc[2] += (x.x - c.x) * f.y - (x.y - c.y) * f.x + s.torque[i].z;
            }
            *w = acc;
        }
        for b in 0..self.blocks.len() {
            self.move_block(b, flow, h);
        }
        self.time += h;
        self.steps += 1;
        self.place_members();
    }

    /// The surface slope ∇η at (x, y) (module docs).
    fn slope(&self, flow: &impl FlowField, x: f64, y: f64) -> [f64; 2] {
        let [dx, dy] = flow.spacing();
        let min = self.params.slope_depth;
        let eta = |px: f64, py: f64| {
            flow.sample(px, py)
                .filter(|s| s.depth >= min)
                .map(|s| s.surface())
        };
        let diff = |a: Option<f64>, b: Option<f64>, l: f64| match (a, b) {
            (Some(a), Some(b)) => (b - a) / (2.0 * l),
            _ => 0.0,
        };
        [
            diff(eta(x - dx, y), eta(x + dx, y), dx),
            diff(eta(x, y - dy), eta(x, y + dy), dy),
        ]
    }

    /// Moves block `b` by one sub-step `h` [s] under the flow and its contact wrench.
    fn move_block(&mut self, b: usize, flow: &impl FlowField, h: f64) {
        let p = &self.params;
        let pc = &self.pieces[b];
        let sh = pc.shape;
        if self.state[b].phase == Phase::Out {
            return;
        }
        let c = self.blocks.centre[b];
        let Some(s) = flow.sample(c.x, c.y) else {
            let st = &mut self.state[b];
            st.phase = Phase::Out;
            self.blocks.velocity[b] = Vec3::ZERO;
            self.blocks.angular_velocity[b] = Vec3::ZERO;
            return;
        };
        let slope = self.slope(flow, c.x, c.y);
        let st = &mut self.state[b];
        if st.phase == Phase::Floating {
            st.floated += h;
        }
        let (rho, g) = (p.water_density, p.gravity);
        let m = flooded_mass(
            pc.mass,
            sh.volume(),
            pc.floodable_fraction,
            pc.flooding_time,
            rho,
            st.floated,
        );
        let bal = balance(m, sh.plan_area(), sh.height, s.depth, rho, g);
        let w = bal.wet_height;
        let vw = sh.plan_area() * w;
        let me = m + p.added_mass_coefficient * rho * vw;
        let fi = rho * vw * (1.0 + p.added_mass_coefficient) * g;
        let [fcx, fcy, tz] = self.wrench[b];
        let f = [fcx - fi * slope[0], fcy - fi * slope[1]];
        let e3 = self.blocks.orientation[b] * Vec3::X;
        let e = [e3.x, e3.y];
        let v = self.blocks.velocity[b];
        let u = s.velocity;
        let ur = [u[0] - v.x, u[1] - v.y];
        let k = drag_factor(rho, p.drag_coefficient, w, sh.length, sh.width, e, ur);
        let n = bal.normal;
        let vn = slide(
            me,
            [v.x, v.y],
            u,
            f,
            k,
            n,
            p.static_friction,
            p.kinetic_friction,
            h,
            &mut st.stuck,
        );
        // Yaw: contact torque, rotational drag (implicit), bed friction.
        let iz = m * sh.yaw_gyration();
        let om = self.blocks.angular_velocity[b].z;
        let (l4, b4) = (sh.length.powi(4), sh.width.powi(4));
        let kr = rho * p.drag_coefficient * w * (l4 + b4) / 64.0 * om.abs();
        let den = iz + h * kr;
        let mut omn = (iz * om + h * tz) / den;
        if n > 0.0 {
            if st.stuck {
                omn = 0.0;
            } else {
                let dw = h * p.kinetic_friction * n * sh.yaw_gyration().sqrt() / den;
                omn = if omn.abs() <= dw {
                    0.0
                } else {
                    omn - dw * omn.signum()
                };
            }
        }
        st.phase = bal.phase;
        st.wet_height = w;
        st.normal = n;
        let mut rs = RigidState {
            centre: c,
            velocity: Vec3::new(vn[0], vn[1], 0.0),
            orientation: self.blocks.orientation[b],
            angular_velocity: Vec3::new(0.0, 0.0, omn),
        };
        let body = crate::rigid::blocks::Body {
            mass: m,
            inertia: inertia(&sh, m),
        };
        drift(&mut rs, &body, h);
        let bottom = if bal.phase == Phase::Floating {
            s.surface() - w
        } else {
            s.bed
        };
        rs.centre.z = bottom + 0.5 * sh.height;
        self.blocks.displacement[b] += rs.centre - c;
        self.blocks.set_state(b, rs);
        self.blocks.mass[b] = m;
        self.blocks.inertia[b] = body.inertia;
    }

    /// Puts the member spheres where their blocks are, in the contact plane z = 0, and
    /// rebuilds the neighbour list when it may miss a pair.
    fn place_members(&mut self) {
        let d = &mut self.dem;
        let mut moved = 0.0f64;
        for b in 0..self.blocks.len() {
            let (c, q) = (self.blocks.centre[b], self.blocks.orientation[b]);
            let (v, w) = (self.blocks.velocity[b], self.blocks.angular_velocity[b]);
            for k in self.blocks.members[b].clone() {
                let k = k as usize;
                let r = q * self.blocks.member_offset[k];
                let x = Vec3::new(c.x + r.x, c.y + r.y, 0.0);
                let i = self.slots[k] as usize;
                moved = moved.max((x - d.spheres.position[i]).length());
                d.spheres.position[i] = x;
                d.spheres.velocity[i] = Vec3::new(v.x, v.y, 0.0) + w.cross(r);
                d.spheres.angular_velocity[i] = w;
            }
        }
        d.neighbors.note_drift(moved);
        if d.neighbors.needs_rebuild(&d.spheres, &d.domain) {
            d.rebuild_lists(self.time);
            self.refresh_slots();
        }
    }

    /// The state to save.
    pub fn snapshot(&self) -> DebrisState {
        let d = &self.dem;
        DebrisState {
            time: self.time,
            steps: self.steps,
            blocks: self.blocks.clone(),
            pieces: self.state.clone(),
            spheres: d.spheres.clone(),
            reference: d.neighbors.reference().to_vec(),
            built_at: d.wall_contacts.built_at,
            contacts: d.contacts.save(&d.neighbors, &d.spheres),
            walls: d.wall_contacts.save(&d.spheres),
        }
    }

    /// Puts a saved state back; refused if it is not of these pieces.
    pub fn restore(&mut self, s: DebrisState) -> Result<(), String> {
        if s.blocks.len() != self.pieces.len()
            || s.pieces.len() != self.pieces.len()
            || s.blocks.member_id != self.blocks.member_id
            || s.spheres.len() != self.dem.spheres.len()
        {
            return Err(format!(
                "the saved debris has {} pieces and {} spheres, the scenario {} and {}",
                s.blocks.len(),
                s.spheres.len(),
                self.pieces.len(),
                self.dem.spheres.len()
            ));
        }
        self.time = s.time;
        self.steps = s.steps;
        self.blocks = s.blocks;
        self.state = s.pieces;
        self.dem.spheres = s.spheres;
        self.dem
            .restore_lists(&s.reference, s.built_at, &s.contacts, &s.walls);
        self.refresh_slots();
        Ok(())
    }
}

/// Principal moments of a solid box of mass `m` [kg]: M (B² + H²)/12, M (L² + H²)/12,
/// M (L² + B²)/12 [kg m²].
fn inertia(s: &BoxShape, m: f64) -> Vec3 {
    let (l2, b2, h2) = (s.length.powi(2), s.width.powi(2), s.height.powi(2));
    Vec3::new(b2 + h2, l2 + h2, l2 + b2) * (m / 12.0)
}
