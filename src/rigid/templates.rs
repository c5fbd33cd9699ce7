//! Block templates: the shape of an armour unit as a cluster of spheres, with its mass
//! properties.
//!
//! A template is defined by member spheres (centre offset and diameter) in a *definition frame*
//! of the user's choosing. Construction computes:
//!
//! 1. the moments of the union of the spheres, overlaps counted once (`mass_properties`);
//! 2. member mass fractions that make the members carry the union's mass, centroid and inertia
//!    (`member_masses`), which is what the PMS recovery [34][35] needs;
//! 3. the *body frame*: origin at the centroid of the members' mass, axes along the principal
//!    axes of their inertia (Jacobi, `jacobi`). Member offsets q_i⁰ are stored in this frame, so
//!    the inertia in the body frame is diagonal, I_g0 = diag(I₁, I₂, I₃), as [49] uses it.
//!
//! The rotation from the body frame to the definition frame is kept (`principal_axes`), so a
//! block placed with the orientation Q_def of its definition frame has the body orientation
//! Q = Q_def · principal_axes.
//!
//! Geometry and mass are separate: a template holds volumes and second moments per unit density
//! [m⁵]; multiply by the block density ρ_s [kg m⁻³] for masses and inertias. Engineers size armour
//! by nominal diameter D_n = V^(1/3) (D_n50 of a grading) or by unit mass W = ρ_s V:
//! `with_nominal_diameter` and `with_mass` rescale a template exactly (V ∝ s³, J ∝ s⁵).

use serde::{Deserialize, Serialize};

use crate::math::{Mat3, Quat, Vec3};

use super::jacobi::principal_axes;
use super::mass_properties::{union_of_spheres, Moments, DEFAULT_POLAR_POINTS};
use super::member_masses::{fit_mass_fractions, member_distribution};

/// One member sphere of a template, in the body frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Member {
    /// Offset q_i⁰ of the sphere centre from the block centre, in the body frame [m].
    pub offset: Vec3,
    /// Radius [m].
    pub radius: f64,
    /// Share of the block mass carried by this member, f_i = m_i / M [-] (Σ f_i = 1).
    pub mass_fraction: f64,
}

/// The shape of a block and its mass properties per unit density.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct BlockTemplate {
    /// Name ("cube", "tetrapod", a user's label).
    pub name: String,
    /// Member spheres in the body frame.
    pub members: Vec<Member>,
    /// Volume V of the union of the spheres [m³].
    pub volume: f64,
    /// Principal moments of inertia per unit density, J = I / ρ_s, along the body axes [m⁵].
    pub principal_inertia: Vec3,
    /// Rotation from the body frame to the definition frame [-].
    pub principal_axes: Quat,
    /// The block centre in the definition frame [m].
    pub centre_in_definition: Vec3,
    /// The union's moments in the definition frame (for checks and reports).
    pub union: Moments,
    /// How far the members' mass distribution is from the union's: the larger of the centroid
    /// offset and the largest inertia difference, each relative to the union's radius of gyration
    /// and largest principal moment [-]. At the quadrature's accuracy (below 1e-5) for the library
    /// shapes and most clusters of ten or more spheres; a few-sphere cluster with overlaps (two
    /// spheres: about 10⁻¹) cannot be carried exactly by its members, see `member_masses`.
    pub representation_error: f64,
}

/// A template that cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TemplateError {
    /// No spheres were given.
    #[error("block template `{0}` has no spheres")]
    Empty(String),
    /// A sphere with a non-finite centre or a diameter that is not positive and finite.
    #[error("block template `{name}`: sphere {index} has centre [{}, {}, {}] and diameter {diameter} (need finite, diameter > 0)", .centre[0], .centre[1], .centre[2])]
    BadSphere {
        /// Template name.
        name: String,
        /// Index of the sphere in the list.
        index: usize,
        /// Its centre [m].
        centre: [f64; 3],
        /// Its diameter [m].
        diameter: f64,
    },
}

impl BlockTemplate {
    /// A template from spheres given as (centre offset [m], diameter [m]) in any frame, with the
    /// default direction quadrature (`mass_properties::DEFAULT_POLAR_POINTS`).
    pub fn from_spheres(
        name: &str,
        spheres: &[(Vec3, f64)],
    ) -> Result<BlockTemplate, TemplateError> {
        Self::from_spheres_with_quadrature(name, spheres, DEFAULT_POLAR_POINTS)
    }

    /// As `from_spheres`, with `polar_points` nodes in the polar direction of the quadrature.
    pub fn from_spheres_with_quadrature(
        name: &str,
        spheres: &[(Vec3, f64)],
        polar_points: usize,
    ) -> Result<BlockTemplate, TemplateError> {
        if spheres.is_empty() {
            return Err(TemplateError::Empty(name.into()));
        }
        for (index, &(c, d)) in spheres.iter().enumerate() {
            if !(c.is_finite() && d.is_finite() && d > 0.0) {
                return Err(TemplateError::BadSphere {
                    name: name.into(),
                    index,
                    centre: c.to_array(),
                    diameter: d,
                });
            }
        }
        let centres: Vec<Vec3> = spheres.iter().map(|s| s.0).collect();
        let radii: Vec<f64> = spheres.iter().map(|s| 0.5 * s.1).collect();
        let union = union_of_spheres(&centres, &radii, polar_points);
        let fractions = fit_mass_fractions(&centres, &radii, &union);
        let (centre, j_def) = member_distribution(&centres, &radii, &fractions);
        let v = union.total.volume;
        let (moments, axes) = principal_axes(v * j_def);
        let members = (0..centres.len())
            .map(|i| Member {
                offset: axes.transpose() * (centres[i] - centre),
                radius: radii[i],
                mass_fraction: fractions[i],
            })
            .collect();

        let j_union = union.total.inertia_per_density();
        let scale_i = j_union
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, x| a.max(x.abs()));
        let r_gyr = (0.5 * (j_union.x_axis.x + j_union.y_axis.y + j_union.z_axis.z) / v).sqrt();
        let inertia_err = (v * j_def - j_union)
            .to_cols_array()
            .iter()
            .fold(0.0f64, |a, x| a.max(x.abs()))
            / scale_i;
        let centre_err = (centre - union.total.centroid()).length() / r_gyr;

        Ok(BlockTemplate {
            name: name.into(),
            members,
            volume: v,
            principal_inertia: moments,
            principal_axes: Quat::from_mat3(&axes).normalize(),
            centre_in_definition: centre,
            union: union.total,
            representation_error: inertia_err.max(centre_err),
        })
    }

    /// Nominal diameter D_n = V^(1/3) [m] (the edge of the cube of equal volume).
    pub fn nominal_diameter(&self) -> f64 {
        self.volume.cbrt()
    }

    /// Radius of the smallest sphere about the centre that holds the whole block [m].
    pub fn bounding_radius(&self) -> f64 {
        self.members
            .iter()
            .map(|m| m.offset.length() + m.radius)
            .fold(0.0, f64::max)
    }

    /// Mass M = ρ_s V [kg] at density ρ_s [kg m⁻³].
    pub fn mass(&self, density: f64) -> f64 {
        density * self.volume
    }

    /// Principal moments of inertia ρ_s J [kg m²] at density ρ_s [kg m⁻³].
    pub fn inertia(&self, density: f64) -> Vec3 {
        density * self.principal_inertia
    }

    /// Member masses m_i = f_i M [kg] at density ρ_s [kg m⁻³]; they sum to M.
    pub fn member_masses(&self, density: f64) -> Vec<f64> {
        let m = self.mass(density);
        self.members.iter().map(|s| s.mass_fraction * m).collect()
    }

    /// Member spin inertias I_i = (2/5) m_i r_i² [kg m²] (solid spheres), consistent with the
    /// block inertia.
    pub fn member_inertias(&self, density: f64) -> Vec<f64> {
        let m = self.mass(density);
        self.members
            .iter()
            .map(|s| 0.4 * s.mass_fraction * m * s.radius * s.radius)
            .collect()
    }

    /// Body-frame member offsets q_i⁰ [m].
    pub fn offsets(&self) -> Vec<Vec3> {
        self.members.iter().map(|s| s.offset).collect()
    }

    /// The template scaled by the length factor s [-]: offsets and radii × s, V × s³, J × s⁵.
    pub fn scaled(&self, s: f64) -> BlockTemplate {
        let (s3, s5) = (s.powi(3), s.powi(5));
        BlockTemplate {
            name: self.name.clone(),
            members: self
                .members
                .iter()
                .map(|m| Member {
                    offset: s * m.offset,
                    radius: s * m.radius,
                    mass_fraction: m.mass_fraction,
                })
                .collect(),
            volume: s3 * self.volume,
            principal_inertia: s5 * self.principal_inertia,
            principal_axes: self.principal_axes,
            centre_in_definition: s * self.centre_in_definition,
            union: Moments {
                volume: s3 * self.union.volume,
                first: s3 * s * self.union.first,
                second: s5 * self.union.second,
            },
            representation_error: self.representation_error,
        }
    }

    /// The template scaled to the nominal diameter D_n = V^(1/3) [m].
    pub fn with_nominal_diameter(&self, d_n: f64) -> BlockTemplate {
        self.scaled(d_n / self.nominal_diameter())
    }

    /// The template scaled to the unit mass W [kg] at density ρ_s [kg m⁻³]: V = W / ρ_s.
    pub fn with_mass(&self, mass: f64, density: f64) -> BlockTemplate {
        self.with_nominal_diameter((mass / density).cbrt())
    }

    /// Member centres in the world for a block at `centre` [m] with body orientation `q`.
    pub fn member_positions(&self, centre: Vec3, q: Quat) -> Vec<Vec3> {
        let r = Mat3::from_quat(q);
        self.members.iter().map(|m| centre + r * m.offset).collect()
    }
}
