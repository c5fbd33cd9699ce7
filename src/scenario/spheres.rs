//! Sphere sets of a scenario: lists, lattices, random fills and feeders, with the checks on
//! initial positions (inside the domain, on the right side of walls, not overlapping).

use super::checks::{finite, material_of, material_or_default, non_negative, positive};
use super::schema::{
    v3, FeedSet, FileSet, LatticeSet, ListSet, RandomSet, SizeSection, SphereSet, WallSection,
};
use super::{ScenarioError, Source};
use crate::dem::domain::Domain;
use crate::dem::insertion::{
    counts_from_mass_fractions, lattice, random_fill, Feeder, Rng, SizeClass,
};
use crate::dem::material::Material;
use crate::dem::neighbor::close_pairs;
use crate::dem::spheres::{NewSphere, Spheres};
use crate::math::Vec3;

/// How the classes of a set are weighted.
#[derive(Clone, Copy, PartialEq)]
enum Weights {
    /// `count` or `mass_fraction` of `total_mass` (random fills).
    CountsOrFractions,
    /// `count` only, as relative weights (feeds).
    Counts,
}

/// The size classes of a set, checked, with mass fractions turned into counts.
#[allow(clippy::too_many_arguments)]
fn size_classes(
    src: &Source,
    names: &[String],
    materials: &[Material],
    key: &str,
    default: Option<&str>,
    sizes: &[SizeSection],
    total_mass: Option<f64>,
    weights: Weights,
) -> Result<Vec<SizeClass>, ScenarioError> {
    if sizes.is_empty() {
        return Err(src.invalid(&format!("{key}.sizes"), "at least one size class is needed"));
    }
    let mut out = Vec::new();
    let mut fractions = Vec::new();
    for (c, s) in sizes.iter().enumerate() {
        let k = format!("{key}.sizes[{c}]");
        positive(src, &format!("{k}.diameter"), s.diameter)?;
        let m = material_or_default(
            src,
            names,
            &format!("{k}.material"),
            s.material.as_deref(),
            &format!("{key}.material"),
            default,
        )?;
        let rho = materials[m as usize].density;
        match (s.count, s.mass_fraction) {
            (Some(n), None) => out.push(SizeClass { diameter: s.diameter, material: m, density: rho, count: n }),
            (None, Some(_)) if weights == Weights::Counts => {
                return Err(src.invalid(
                    &format!("{k}.mass_fraction"),
                    "a feed weights its size classes by `count` (relative numbers); mass fractions are \
                     for random fills",
                ))
            }
            (None, Some(f)) => {
                non_negative(src, &format!("{k}.mass_fraction"), f)?;
                fractions.push((s.diameter, rho, f));
                out.push(SizeClass { diameter: s.diameter, material: m, density: rho, count: 0 });
            }
            (Some(_), Some(_)) => {
                return Err(src.invalid(&k, "give `count` or `mass_fraction`, not both"));
            }
            (None, None) => {
                let what = if weights == Weights::Counts { "`count`" } else { "`count` or `mass_fraction`" };
                return Err(src.invalid(&k, format!("give {what} for this size class")));
            }
        }
    }
    if weights == Weights::Counts && out.iter().all(|c| c.count == 0) {
        return Err(src.invalid(
            &format!("{key}.sizes"),
            "every class has count = 0: nothing to feed",
        ));
    }
    if !fractions.is_empty() {
        if fractions.len() != out.len() {
            return Err(src.invalid(
                &format!("{key}.sizes"),
                "use either counts or mass fractions for all classes",
            ));
        }
        if fractions.iter().all(|f| f.2 == 0.0) {
            return Err(src.invalid(&format!("{key}.sizes"), "the mass fractions are all zero"));
        }
        let total = total_mass.ok_or_else(|| {
            src.invalid_at(
                &format!("{key}.total_mass"),
                &format!("{key}.sizes"),
                "mass fractions need a total_mass [kg]",
            )
        })?;
        positive(src, &format!("{key}.total_mass"), total)?;
        for (c, n) in counts_from_mass_fractions(total, &fractions)
            .into_iter()
            .enumerate()
        {
            out[c].count = n;
        }
    }
    Ok(out)
}

/// Refuses a region [min, max] of a sphere set that is empty or reaches outside the domain.
pub(super) fn check_region(
    src: &Source,
    key: &str,
    min: [f64; 3],
    max: [f64; 3],
    domain: &Domain,
) -> Result<(), ScenarioError> {
    finite(src, &format!("{key}.min"), &min)?;
    finite(src, &format!("{key}.max"), &max)?;
    let axis = ["x", "y", "z"];
    for k in 0..3 {
        if min[k].partial_cmp(&max[k]) != Some(std::cmp::Ordering::Less) {
            return Err(src.invalid(
                &format!("{key}.max"),
                format!("must exceed min along every axis ({})", axis[k]),
            ));
        }
        let tol = 1e-9 * (domain.max[k] - domain.min[k]);
        if min[k] < domain.min[k] - tol {
            return Err(src.invalid(
                &format!("{key}.min"),
                format!(
                    "the region reaches outside the domain: min {} = {} < domain.min {} = {}",
                    axis[k], min[k], axis[k], domain.min[k]
                ),
            ));
        }
        if max[k] > domain.max[k] + tol {
            return Err(src.invalid(
                &format!("{key}.max"),
                format!(
                    "the region reaches outside the domain: max {} = {} > domain.max {} = {}",
                    axis[k], max[k], axis[k], domain.max[k]
                ),
            ));
        }
    }
    Ok(())
}

pub(super) fn build_spheres(
    src: &Source,
    names: &[String],
    materials: &[Material],
    domain: &Domain,
) -> Result<(Spheres, Vec<Feeder>, Vec<String>), ScenarioError> {
    let mut spheres = Spheres::default();
    let mut feeders = Vec::new();
    // Where each initial sphere comes from, for messages: its key path.
    let mut origin: Vec<String> = Vec::new();
    let axis = ["x", "y", "z"];
    for (i, set) in src.scenario.spheres.iter().enumerate() {
        let key = format!("spheres[{i}]");
        let first = spheres.len();
        match set {
            SphereSet::List(ListSet {
                material,
                spheres: list,
            }) => {
                if list.is_empty() {
                    return Err(src.invalid(&format!("{key}.spheres"), "the list has no sphere"));
                }
                for (k, e) in list.iter().enumerate() {
                    let kk = format!("{key}.spheres[{k}]");
                    positive(src, &format!("{kk}.diameter"), e.diameter)?;
                    finite(src, &format!("{kk}.position"), &e.position)?;
                    finite(src, &format!("{kk}.velocity"), &e.velocity)?;
                    finite(src, &format!("{kk}.angular_velocity"), &e.angular_velocity)?;
                    let m = material_or_default(
                        src,
                        names,
                        &format!("{kk}.material"),
                        e.material.as_deref(),
                        &format!("{key}.material"),
                        material.as_deref(),
                    )?;
                    let x = v3(e.position);
                    if let Some(a) = (0..3).find(|&a| x[a] < domain.min[a] || x[a] > domain.max[a])
                    {
                        return Err(src.invalid(
                            &format!("{kk}.position"),
                            format!(
                                "lies outside the domain: {} = {} is not within [{}, {}]",
                                axis[a], x[a], domain.min[a], domain.max[a]
                            ),
                        ));
                    }
                    spheres.push(NewSphere {
                        position: x,
                        velocity: v3(e.velocity),
                        angular_velocity: v3(e.angular_velocity),
                        radius: 0.5 * e.diameter,
                        material: m,
                        density: materials[m as usize].density,
                        fixed: e.fixed,
                    });
                    origin.push(kk);
                }
            }
            SphereSet::Lattice(LatticeSet {
                material,
                min,
                max,
                spacing,
                diameter,
                velocity,
            }) => {
                positive(src, &format!("{key}.diameter"), *diameter)?;
                positive(src, &format!("{key}.spacing"), *spacing)?;
                finite(src, &format!("{key}.velocity"), velocity)?;
                if spacing < diameter {
                    return Err(src.invalid(
                        &format!("{key}.spacing"),
                        format!("{spacing} m is smaller than the diameter {diameter} m: neighbours would overlap"),
                    ));
                }
                check_region(src, &key, *min, *max, domain)?;
                let m = material_of(src, names, &format!("{key}.material"), Some(material))?;
                let sites = lattice(v3(*min), v3(*max), *spacing);
                if sites.is_empty() {
                    return Err(src.invalid(
                        &format!("{key}.spacing"),
                        format!("the region [min, max] is thinner than one spacing ({spacing} m) along some axis: no sphere fits"),
                    ));
                }
                for x in sites {
                    spheres.push(NewSphere {
                        position: x,
                        velocity: v3(*velocity),
                        angular_velocity: Vec3::ZERO,
                        radius: 0.5 * diameter,
                        material: m,
                        density: materials[m as usize].density,
                        fixed: false,
                    });
                    origin.push(key.clone());
                }
            }
            SphereSet::Random(RandomSet {
                material,
                min,
                max,
                sizes,
                total_mass,
                seed,
                velocity,
            }) => {
                check_region(src, &key, *min, *max, domain)?;
                finite(src, &format!("{key}.velocity"), velocity)?;
                let classes = size_classes(
                    src,
                    names,
                    materials,
                    &key,
                    material.as_deref(),
                    sizes,
                    *total_mass,
                    Weights::CountsOrFractions,
                )?;
                let mut rng = Rng(*seed);
                random_fill(
                    &mut spheres,
                    domain,
                    v3(*min),
                    v3(*max),
                    &classes,
                    v3(*velocity),
                    &mut rng,
                )
                .map_err(|e| {
                    src.invalid(
                        &format!("{key}.sizes"),
                        format!("impossible random fill: {e}"),
                    )
                })?;
                origin.resize(spheres.len(), key.clone());
            }
            SphereSet::Feed(FeedSet {
                material,
                min,
                max,
                rate,
                total,
                start,
                sizes,
                seed,
                velocity,
            }) => {
                positive(src, &format!("{key}.rate"), *rate)?;
                non_negative(src, &format!("{key}.start"), *start)?;
                finite(src, &format!("{key}.velocity"), velocity)?;
                check_region(src, &key, *min, *max, domain)?;
                let classes = size_classes(
                    src,
                    names,
                    materials,
                    &key,
                    material.as_deref(),
                    sizes,
                    None,
                    Weights::Counts,
                )?;
                for (c, class) in classes.iter().enumerate() {
                    if let Some(a) =
                        (0..3).find(|&a| max[a] - min[a] < class.diameter * (1.0 - 1e-9))
                    {
                        return Err(src.invalid(
                            &format!("{key}.sizes[{c}].diameter"),
                            format!(
                                "spheres of diameter {} m do not fit in the feed region, which is {} m wide along {}",
                                class.diameter,
                                max[a] - min[a],
                                axis[a]
                            ),
                        ));
                    }
                }
                feeders.push(Feeder {
                    lo: v3(*min),
                    hi: v3(*max),
                    rate: *rate,
                    start: *start,
                    total: *total,
                    classes,
                    velocity: v3(*velocity),
                    inserted: 0,
                    rng: Rng(*seed),
                });
            }
            SphereSet::File(FileSet {
                material,
                file,
                max_overlap_ratio,
            }) => {
                let m = material_of(src, names, &format!("{key}.material"), Some(material))?;
                non_negative(src, &format!("{key}.max_overlap_ratio"), *max_overlap_ratio)?;
                let path = src.dir.join(file);
                let rows = read_sphere_csv(&path, domain)
                    .map_err(|e| src.invalid(&format!("{key}.file"), e))?;
                let lines: Vec<usize> = rows.iter().map(|r| r.0).collect();
                for (_, row) in rows {
                    spheres.push(NewSphere {
                        position: row.position,
                        velocity: Vec3::ZERO,
                        angular_velocity: Vec3::ZERO,
                        radius: 0.5 * row.diameter,
                        material: m,
                        density: materials[m as usize].density,
                        fixed: row.fixed,
                    });
                    origin.push(format!("{key}.file"));
                }
                let csv = CsvLines {
                    path: &path,
                    lines: &lines,
                    first,
                };
                let ratio = *max_overlap_ratio;
                check_file_overlaps(src, &spheres, domain, &origin, &csv, ratio)?;
                continue;
            }
        }
        check_overlaps(src, &spheres, first, domain, &origin)?;
    }
    Ok((spheres, feeders, origin))
}

/// One sphere of a CSV file.
struct CsvSphere {
    position: Vec3,
    diameter: f64,
    fixed: bool,
}

/// Reads `x,y,z,diameter[,fixed]` rows [m] from `path`, with the 1-based line of each. A
/// first line that does not start with a number is a header; blank lines and lines starting
/// with `#` are skipped. Errors name the file, the line and the reason.
fn read_sphere_csv(
    path: &std::path::Path,
    domain: &Domain,
) -> Result<Vec<(usize, CsvSphere)>, String> {
    let file = path.display();
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the sphere file {file}: {e}"))?;
    let axis = ["x", "y", "z"];
    let mut rows = Vec::new();
    let mut first = true;
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let l = raw.trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        let cols: Vec<&str> = l.split(',').map(str::trim).collect();
        let header = first && cols[0].parse::<f64>().is_err();
        first = false;
        if header {
            continue;
        }
        if cols.len() < 4 || cols.len() > 5 {
            return Err(format!(
                "{file}:{line}: expected 4 or 5 columns `x,y,z,diameter[,fixed]`, found {}",
                cols.len()
            ));
        }
        let names = ["x", "y", "z", "diameter", "fixed"];
        let mut v = [0.0; 5];
        for (c, text) in cols.iter().enumerate() {
            v[c] = text
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    format!(
                        "{file}:{line}: column {} (`{}`) is not a finite number: `{text}`",
                        c + 1,
                        names[c]
                    )
                })?;
        }
        if v[3] <= 0.0 {
            return Err(format!(
                "{file}:{line}: the diameter must be positive, got {}",
                v[3]
            ));
        }
        let fixed = match cols.len() {
            5 if v[4] == 0.0 => false,
            5 if v[4] == 1.0 => true,
            5 => {
                return Err(format!(
                    "{file}:{line}: `fixed` must be 0 or 1, got {}",
                    cols[4]
                ))
            }
            _ => false,
        };
        let x = Vec3::new(v[0], v[1], v[2]);
        if let Some(a) = (0..3).find(|&a| x[a] < domain.min[a] || x[a] > domain.max[a]) {
            return Err(format!(
                "{file}:{line}: the sphere lies outside the domain: {} = {} is not within [{}, {}]",
                axis[a], x[a], domain.min[a], domain.max[a]
            ));
        }
        rows.push((
            line,
            CsvSphere {
                position: x,
                diameter: v[3],
                fixed,
            },
        ));
    }
    if rows.is_empty() {
        return Err(format!("the sphere file {file} holds no sphere"));
    }
    Ok(rows)
}

/// Where the spheres of a file set come from: the file, and the line of each sphere from slot
/// `first` on.
struct CsvLines<'a> {
    path: &'a std::path::Path,
    lines: &'a [usize],
    first: usize,
}

/// Refuses spheres of a file set (from `csv.first` on, against all earlier ones) that overlap
/// by more than `ratio` of the smaller diameter, naming the file and lines.
fn check_file_overlaps(
    src: &Source,
    s: &Spheres,
    domain: &Domain,
    origin: &[String],
    csv: &CsvLines,
    ratio: f64,
) -> Result<(), ScenarioError> {
    let first = csv.first;
    let at = |k: usize| {
        if k >= first {
            format!("{}:{}", csv.path.display(), csv.lines[k - first])
        } else {
            origin[k].clone()
        }
    };
    let mut worst: Option<(usize, usize, f64)> = None;
    for (i, j, d) in new_pairs(s, domain, first) {
        let r = (s.radius[i] + s.radius[j] - d) / (2.0 * s.radius[i].min(s.radius[j]));
        if r > ratio && worst.is_none_or(|w| r > w.2) {
            worst = Some((i, j, r));
        }
    }
    if let Some((i, j, r)) = worst {
        return Err(src.invalid(
            &origin[j],
            format!(
                "spheres overlap by more than max_overlap_ratio = {ratio}: {} and {} (d = {} m \
                 and {} m) overlap by {:.3} of the smaller diameter",
                at(i),
                at(j),
                2.0 * s.radius[i],
                2.0 * s.radius[j],
                r
            ),
        ));
    }
    Ok(())
}

/// The pairs (i < j, j ≥ `first`) of spheres that touch or overlap, with their centre distance
/// [m] (minimum image on periodic axes).
fn new_pairs<'a>(
    s: &'a Spheres,
    domain: &'a Domain,
    first: usize,
) -> impl Iterator<Item = (usize, usize, f64)> + 'a {
    close_pairs(s, domain, 0.0)
        .into_iter()
        .filter_map(move |(i, j)| {
            let (i, j) = (i.min(j) as usize, i.max(j) as usize);
            (j >= first).then(|| {
                (
                    i,
                    j,
                    domain.minimum_image(s.position[j] - s.position[i]).length(),
                )
            })
        })
}

/// Refuses initial spheres that overlap (spheres from `first` on against all earlier ones).
fn check_overlaps(
    src: &Source,
    s: &Spheres,
    first: usize,
    domain: &Domain,
    origin: &[String],
) -> Result<(), ScenarioError> {
    let mut worst: Option<(usize, usize, f64)> = None;
    for (i, j, d) in new_pairs(s, domain, first) {
        let overlap = s.radius[i] + s.radius[j] - d;
        if overlap > 1e-9 * (s.radius[i] + s.radius[j]) && worst.is_none_or(|w| (j, i) < (w.1, w.0))
        {
            worst = Some((i, j, overlap));
        }
    }
    if let Some((i, j, overlap)) = worst {
        let at = |k: usize| {
            format!(
                "sphere {} ({}, d = {} m, at ({}, {}, {}))",
                s.id[k],
                origin[k],
                2.0 * s.radius[k],
                s.position[k].x,
                s.position[k].y,
                s.position[k].z
            )
        };
        return Err(src.invalid(
            &origin[j],
            format!(
                "initial spheres overlap: {} and {} overlap by {:.3e} m ({:.1}% of the smaller radius); \
                 move them apart",
                at(i),
                at(j),
                overlap,
                100.0 * overlap / s.radius[i].min(s.radius[j])
            ),
        ));
    }
    Ok(())
}

/// Refuses initial spheres whose centre lies on the wrong side of a wall (behind a plane, out of
/// a container, inside an obstacle): the wall would throw them out with a huge force.
pub(super) fn check_walls(
    src: &Source,
    s: &Spheres,
    origin: &[String],
) -> Result<(), ScenarioError> {
    for (w, wall) in src.scenario.walls.iter().enumerate() {
        let name = wall
            .common()
            .0
            .clone()
            .unwrap_or_else(|| format!("{}{w}", wall.kind()));
        for (k, &x) in s.position.iter().enumerate() {
            // A fixed sphere does not meet walls (`dem::wall_contacts`): the under-layer's
            // stones are centred on its plane.
            if s.fixed[k] {
                continue;
            }
            let wrong = match wall {
                WallSection::Plane(p) => {
                    let n = v3(p.normal).normalize_or_zero();
                    (x - v3(p.point)).dot(n) < 0.0
                }
                WallSection::Box(b) => {
                    let inside = (0..3).all(|a| x[a] >= b.min[a] && x[a] <= b.max[a]);
                    inside != b.inside
                }
                WallSection::Cylinder(c) => {
                    let (a, e) = (v3(c.start), v3(c.end));
                    let u = (e - a).normalize_or_zero();
                    let t = (x - a).dot(u);
                    let rho = ((x - a) - t * u).length();
                    let within = t >= 0.0 && t <= (e - a).length();
                    within
                        && if c.inside {
                            rho > c.radius
                        } else {
                            rho < c.radius
                        }
                }
                WallSection::Mesh(_) => false,
            };
            if wrong {
                let side = match wall {
                    WallSection::Plane(_) => {
                        "behind the plane (on the side its normal points away from)"
                    }
                    WallSection::Box(b) if b.inside => "outside the box container",
                    WallSection::Cylinder(c) if c.inside => "outside the tube",
                    _ => "inside the solid obstacle",
                };
                return Err(src.invalid(
                    &origin[k],
                    format!(
                        "sphere {} at ({}, {}, {}) starts {side} of wall `{name}` (wall[{w}]); \
                         spheres must start on the open side of every wall",
                        s.id[k], x.x, x.y, x.z
                    ),
                ));
            }
        }
    }
    Ok(())
}
