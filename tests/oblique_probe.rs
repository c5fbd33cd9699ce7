mod common;
use common::*;
use riprap::dem::material::{ContactModel, Damping, NormalSpring};
use riprap::math::Vec3;

#[test]
fn probe() {
    let r = 0.01;
    for (name, spring) in [("lin", NormalSpring::Linear{stiffness: 2e4}), ("hertz", NormalSpring::Hertz)] {
    for e in [1.0, 0.9, 0.5] {
    for ratio in [3.0, 6.0, 20.0] {
    for steps in [200.0, 1000.0] {
        let mu = 0.3;
        let mat = material(2500.0, 5e7, 0.3, mu, e);
        let model = ContactModel::Voigt { spring, damping: Damping::Restitution };
        let vn = 1.0; let vt = ratio * mu * 3.5 * (1.0 + e) * vn / 3.0;
        let m = sphere_mass(2500.0, r);
        let tc = match spring { NormalSpring::Hertz => { let k = 4.0/3.0*e_star(&mat,&mat)*r.sqrt(); hertz_theory(k, m, vn).duration }, _ => std::f64::consts::PI*(m/2e4f64).sqrt() };
        let dt = tc / steps;
        let mut d = dem(mat, model, open_box(1.0), dt);
        d.walls.push(plane_wall(Vec3::ZERO, Vec3::Z));
        d.add_sphere(Vec3::new(0.0,0.0,r + 10.37*dt*vn), Vec3::new(vt, 0.0, -vn), Vec3::ZERO, r, 0);
        let imp = run_impact(d, 2.0*tc, 100000);
        let em = imp.restitution();
        let vt2 = vt - mu*(1.0+em)*vn;
        let w2 = 2.5*mu*(1.0+em)*vn/r;
        let s = imp.state;
        eprintln!("{name} e={e} vt/vn={:.2} steps={steps}: em={em:.5} vt' {:.6} vs {:.6} (Δ rel to impulse {:+.3e}), w {:.4} vs {:.4} ({:+.3e})", vt/vn, s.v[0].x, vt2, (s.v[0].x-vt2)/(vt-vt2), s.w[0].y, w2, (s.w[0].y-w2)/w2);
    }}}}
}
