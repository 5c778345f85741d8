//! Mesh generation for the table, from [`TableSpec`] alone.
//!
//! Everything is built in physics coordinates (z up, see [`crate::table::geometry`]) and mapped to
//! Bevy's y-up world when the mesh is finished. The functions are pure so that they can be
//! tested without a renderer.

use bevy::{
    asset::RenderAssetUsages,
    math::{DVec2, DVec3},
    mesh::{Indices, PrimitiveTopology},
    prelude::*,
};

use crate::table::geometry::{CushionSegment, Pocket, Rail, TableSpec, to_world};

/// Collects flat-shaded triangles in physics coordinates.
#[derive(Debug, Default)]
pub struct MeshBuilder {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    uvs: Vec<[f32; 2]>,
    indices: Vec<u32>,
}

impl MeshBuilder {
    /// Adds a convex planar polygon (as a triangle fan), wound so that its normal points to
    /// the side of `outward`. Degenerate polygons are skipped.
    pub fn polygon_facing(&mut self, points: &[DVec3], outward: DVec3) {
        if points.len() < 3 {
            return;
        }
        let mut normal = DVec3::ZERO;
        for i in 1..points.len() - 1 {
            normal += (points[i] - points[0]).cross(points[i + 1] - points[0]);
        }
        if normal.length_squared() < 1e-24 {
            return;
        }
        let flip = normal.dot(outward) < 0.0;
        let normal = if flip { -normal } else { normal }.normalize();
        let base = self.positions.len() as u32;
        for p in points {
            self.positions.push(to_world(*p).to_array());
            self.normals.push(to_world(normal).to_array());
            // Planar projection is enough for untextured, lightly textured surfaces.
            self.uvs.push([p.x as f32, (p.y + p.z) as f32]);
        }
        for i in 1..points.len() as u32 - 1 {
            if flip {
                self.indices.extend([base, base + i + 1, base + i]);
            } else {
                self.indices.extend([base, base + i, base + i + 1]);
            }
        }
    }

    /// Adds a flat region in the plane, swept along `samples` of a parameter `u`: at each
    /// sample `bounds(u)` gives the interval of the other parameter `v` that belongs to the
    /// region (or `None`), and `point(u, v)` the physics point. Neighbouring samples form
    /// trapezoids, facing `up`.
    pub fn swept_region(
        &mut self,
        samples: &[f64],
        bounds: impl Fn(f64) -> Option<(f64, f64)>,
        point: impl Fn(f64, f64) -> DVec3,
        up: DVec3,
    ) {
        for pair in samples.windows(2) {
            let (u0, u1) = (pair[0], pair[1]);
            let (Some((a0, b0)), Some((a1, b1))) = (bounds(u0), bounds(u1)) else {
                continue;
            };
            self.polygon_facing(
                &[point(u0, a0), point(u1, a1), point(u1, b1), point(u0, b0)],
                up,
            );
        }
    }

    /// Number of triangles so far.
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// The finished mesh, in Bevy's world coordinates.
    pub fn build(self) -> Mesh {
        Mesh::new(
            PrimitiveTopology::TriangleList,
            RenderAssetUsages::RENDER_WORLD,
        )
        .with_inserted_attribute(Mesh::ATTRIBUTE_POSITION, self.positions)
        .with_inserted_attribute(Mesh::ATTRIBUTE_NORMAL, self.normals)
        .with_inserted_attribute(Mesh::ATTRIBUTE_UV_0, self.uvs)
        .with_inserted_indices(Indices::U32(self.indices))
    }
}

/// Samples from `start` to `end`: evenly spaced, plus the edges of every pocket hole along
/// the chosen axis so that the holes' extreme points are on the mesh.
fn samples(start: f64, end: f64, pockets: &[Pocket], along: impl Fn(DVec2) -> f64) -> Vec<f64> {
    const EVEN: usize = 600;
    let mut samples: Vec<f64> = (0..=EVEN)
        .map(|i| start + (end - start) * i as f64 / EVEN as f64)
        .collect();
    for pocket in pockets {
        let c = along(pocket.centre);
        // Just inside the hole's extremes, where the arc is steepest.
        for offset in [-1.0, -0.999, -0.99, 0.99, 0.999, 1.0] {
            let u = c + offset * pocket.radius;
            if (start..=end).contains(&u) {
                samples.push(u);
            }
        }
    }
    samples.sort_by(f64::total_cmp);
    samples.dedup();
    samples
}

/// Half-chord of a pocket hole at distance `d` from its centre along the sweep axis.
fn half_chord(pocket: &Pocket, d: f64) -> Option<f64> {
    let h2 = pocket.radius * pocket.radius - d * d;
    (h2 > 0.0).then(|| h2.sqrt())
}

/// The cloth on the bed, out to the back of the cushions, with the pocket holes cut out (none
/// on the carom table).
///
/// Each column of the sweep keeps the part below the nearest hole at either end; the little
/// cloth that hides behind a hole under the rails is dropped.
pub fn cloth(spec: &TableSpec) -> Mesh {
    let pockets = spec.pockets();
    let edge = spec.half_extents() + DVec2::splat(spec.cushion_depth);
    let xs = samples(-edge.x, edge.x, &pockets, |c| c.x);
    let mut builder = MeshBuilder::default();
    builder.swept_region(
        &xs,
        |x| {
            let (mut low, mut high) = (-edge.y, edge.y);
            for pocket in &pockets {
                if let Some(h) = half_chord(pocket, x - pocket.centre.x) {
                    if pocket.centre.y > 0.0 {
                        high = high.min(pocket.centre.y - h);
                    } else {
                        low = low.max(pocket.centre.y + h);
                    }
                }
            }
            (low < high).then_some((low, high))
        },
        |x, y| DVec3::new(x, y, 0.0),
        DVec3::Z,
    );
    builder.build()
}

/// The top surfaces of the four wooden rails, with the pocket holes cut out, and the outer
/// apron down to `apron_bottom` (negative: below the cloth).
pub fn rails(spec: &TableSpec, apron_bottom: f64) -> Mesh {
    let pockets = spec.pockets();
    let inner = spec.half_extents() + DVec2::splat(spec.cushion_depth);
    let outer = spec.outer_half_extents();
    let top = spec.rail_height;
    let mut builder = MeshBuilder::default();

    // Long rails span the full length, corners included; short rails fit between them.
    let xs = samples(-outer.x, outer.x, &pockets, |c| c.x);
    for sign in [1.0, -1.0] {
        builder.swept_region(
            &xs,
            |x| {
                let mut low = inner.y;
                for pocket in pockets.iter().filter(|p| p.centre.y * sign > 0.0) {
                    if let Some(h) = half_chord(pocket, x - pocket.centre.x) {
                        low = low.max(pocket.centre.y * sign + h);
                    }
                }
                (low < outer.y).then_some((low, outer.y))
            },
            |x, v| DVec3::new(x, sign * v, top),
            DVec3::Z,
        );
    }
    let ys = samples(-inner.y, inner.y, &pockets, |c| c.y);
    for sign in [1.0, -1.0] {
        builder.swept_region(
            &ys,
            |y| {
                let mut low = inner.x;
                for pocket in pockets.iter().filter(|p| p.centre.x * sign > 0.0) {
                    if let Some(h) = half_chord(pocket, y - pocket.centre.y) {
                        low = low.max(pocket.centre.x * sign + h);
                    }
                }
                (low < outer.x).then_some((low, outer.x))
            },
            |y, u| DVec3::new(sign * u, y, top),
            DVec3::Z,
        );
    }

    // The apron: the outside faces of the rails, down to below the bed.
    let corners = [
        DVec2::new(-outer.x, -outer.y),
        DVec2::new(outer.x, -outer.y),
        DVec2::new(outer.x, outer.y),
        DVec2::new(-outer.x, outer.y),
    ];
    for i in 0..4 {
        let (a, b) = (corners[i], corners[(i + 1) % 4]);
        let mid = (a + b) / 2.0;
        builder.polygon_facing(
            &[
                a.extend(apron_bottom),
                b.extend(apron_bottom),
                b.extend(top),
                a.extend(top),
            ],
            mid.extend(0.0),
        );
    }
    builder.build()
}

/// The cushion cross-section as (depth behind the nose, height) points: the nose, the
/// undercut to the cloth, the back against the rail and the sloped top.
fn cushion_profile(spec: &TableSpec) -> [DVec2; 5] {
    let nose = spec.cushion_nose_height;
    let top = spec.rail_height;
    let depth = spec.cushion_depth;
    [
        DVec2::new(0.0, nose),
        DVec2::new(0.3 * depth, 0.0),
        DVec2::new(depth, 0.0),
        DVec2::new(depth, top),
        DVec2::new(0.2 * depth, top),
    ]
}

/// One cushion as a prism of the profile, its ends cut back along the pocket jaws.
fn add_cushion(builder: &mut MeshBuilder, spec: &TableSpec, segment: &CushionSegment) {
    let profile = cushion_profile(spec);
    // Along the rail, each end moves toward its pocket as the depth grows.
    let start = |depth: f64| segment.start - segment.start_jaw_slope * depth;
    let end = |depth: f64| segment.end + segment.end_jaw_slope * depth;
    let point = |along: f64, p: DVec2| spec.rail_point(segment.rail, along, p.x, p.y);
    // The prism is convex, so every face points away from its centre.
    let centre = point(
        (segment.start + segment.end) / 2.0,
        DVec2::new(spec.cushion_depth / 2.0, spec.rail_height / 2.0),
    );
    let n = profile.len();
    for i in 0..n {
        let (p, q) = (profile[i], profile[(i + 1) % n]);
        let face = [
            point(start(p.x), p),
            point(end(p.x), p),
            point(end(q.x), q),
            point(start(q.x), q),
        ];
        let middle = face.iter().sum::<DVec3>() / 4.0;
        builder.polygon_facing(&face, middle - centre);
    }
    for cap in [
        profile.map(|p| point(start(p.x), p)),
        profile.map(|p| point(end(p.x), p)),
    ] {
        let middle = cap.iter().sum::<DVec3>() / cap.len() as f64;
        builder.polygon_facing(&cap, middle - centre);
    }
}

/// The rubber cushions, covered in cloth: six between the pockets, or the carom table's four.
pub fn cushions(spec: &TableSpec) -> Mesh {
    let mut builder = MeshBuilder::default();
    for segment in &spec.cushions() {
        add_cushion(&mut builder, spec, segment);
    }
    builder.build()
}

/// The pocket liners: for each hole a tube, seen from inside, from `depth` below the cloth up
/// to the cloth where the hole opens onto the playing area and up to the rail top where it
/// cuts through the rail, closed by a floor.
pub fn pocket_liners(spec: &TableSpec, depth: f64) -> Mesh {
    const SEGMENTS: usize = 64;
    let inner = spec.half_extents() + DVec2::splat(spec.cushion_depth);
    let mut builder = MeshBuilder::default();
    for pocket in spec.pockets() {
        let at = |i: usize| {
            let angle = std::f64::consts::TAU * i as f64 / SEGMENTS as f64;
            pocket.centre + pocket.radius * DVec2::from_angle(angle)
        };
        let wall_top = |p: DVec2| {
            if p.x.abs() > inner.x || p.y.abs() > inner.y {
                spec.rail_height
            } else {
                0.0
            }
        };
        for i in 0..SEGMENTS {
            let (a, b) = (at(i), at(i + 1));
            // Split each wall piece where the wall top steps, so no piece pokes above the
            // cloth inside the pocket mouth.
            let top = wall_top(a).min(wall_top(b));
            let inward = (pocket.centre - (a + b) / 2.0).extend(0.0);
            builder.polygon_facing(
                &[
                    a.extend(-depth),
                    b.extend(-depth),
                    b.extend(top),
                    a.extend(top),
                ],
                inward,
            );
        }
        let floor: Vec<DVec3> = (0..SEGMENTS).map(|i| at(i).extend(-depth)).collect();
        builder.polygon_facing(&floor, DVec3::Z);
    }
    builder.build()
}

/// Where the diamond sights sit on the rail tops: at the eighths of each long rail and the
/// quarters of each short rail, along the middle of the rail: seven and three on the carom
/// table, six and three on a pocketed one (the side pocket takes the middle of the long rail).
pub fn diamond_positions(spec: &TableSpec) -> Vec<(Rail, DVec3)> {
    let depth = spec.cushion_depth + spec.rail_width / 2.0;
    let height = spec.rail_height;
    let mut positions = Vec::new();
    let long: &[i32] = if spec.has_pockets() {
        &[-3, -2, -1, 1, 2, 3]
    } else {
        &[-3, -2, -1, 0, 1, 2, 3]
    };
    for rail in [Rail::Left, Rail::Right] {
        for &k in long {
            let along = spec.length * f64::from(k) / 8.0;
            positions.push((rail, spec.rail_point(rail, along, depth, height)));
        }
    }
    for rail in [Rail::Head, Rail::Foot] {
        for k in [-1, 0, 1] {
            let along = spec.width * f64::from(k) / 4.0;
            positions.push((rail, spec.rail_point(rail, along, depth, height)));
        }
    }
    positions
}

#[cfg(test)]
mod tests {
    use super::*;
    use bevy::mesh::VertexAttributeValues;

    fn positions(mesh: &Mesh) -> Vec<Vec3> {
        match mesh.attribute(Mesh::ATTRIBUTE_POSITION) {
            Some(VertexAttributeValues::Float32x3(p)) => p.iter().map(|&p| p.into()).collect(),
            other => panic!("unexpected positions {other:?}"),
        }
    }

    #[test]
    fn cloth_spans_the_bed_but_not_the_pocket_holes() {
        let spec = TableSpec::default();
        let mesh = cloth(&spec);
        let points = positions(&mesh);
        assert!(points.iter().all(|p| p.y == 0.0));
        let max_x = points.iter().map(|p| p.x).fold(f32::MIN, f32::max);
        assert!((f64::from(max_x) - (spec.length / 2.0 + spec.cushion_depth)).abs() < 1e-4);
        // No cloth vertex lies strictly inside a hole.
        for pocket in spec.pockets() {
            for p in &points {
                let d = crate::table::geometry::to_table_plane(*p).distance(pocket.centre);
                assert!(
                    d > pocket.radius - 1e-6,
                    "cloth vertex {p} inside {pocket:?}"
                );
            }
        }
    }

    #[test]
    fn cushion_noses_sit_at_the_specified_height() {
        let spec = TableSpec::default();
        let mesh = cushions(&spec);
        let points = positions(&mesh);
        let h = spec.half_extents();
        // The vertices at the playing-surface edge are the nose line.
        let nose: Vec<&Vec3> = points
            .iter()
            .filter(|p| (f64::from(p.z.abs()) - h.y).abs() < 1e-6)
            .collect();
        assert!(!nose.is_empty());
        for p in nose {
            assert!((f64::from(p.y) - spec.cushion_nose_height).abs() < 1e-6);
        }
    }

    #[test]
    fn every_face_of_a_cushion_points_outward() {
        let spec = TableSpec::default();
        for segment in spec.cushions() {
            let mut builder = MeshBuilder::default();
            add_cushion(&mut builder, &spec, &segment);
            // 5 quads and 2 pentagons: 5 * 2 + 2 * 3 triangles.
            assert_eq!(builder.triangle_count(), 16);
            let points: Vec<Vec3> = builder.positions.iter().map(|&p| p.into()).collect();
            let centre = points.iter().sum::<Vec3>() / points.len() as f32;
            for triangle in builder.indices.chunks(3) {
                let [a, b, c] = [0, 1, 2].map(|k| points[triangle[k] as usize]);
                let normal = (b - a).cross(c - a);
                let middle = (a + b + c) / 3.0;
                assert!(
                    normal.dot(middle - centre) > 0.0,
                    "{segment:?}: inward face"
                );
            }
        }
    }

    #[test]
    fn diamonds_are_on_the_rails() {
        let spec = TableSpec::default();
        let diamonds = diamond_positions(&spec);
        assert_eq!(diamonds.len(), 18);
        for (_, p) in diamonds {
            let outside = p.x.abs() > spec.length / 2.0 + spec.cushion_depth
                || p.y.abs() > spec.width / 2.0 + spec.cushion_depth;
            assert!(outside);
            assert_eq!(p.z, spec.rail_height);
        }
    }

    #[test]
    fn the_carom_table_is_drawn_without_holes_and_with_a_closed_cushion_frame() {
        let spec = TableSpec::carom();
        // The cloth is the whole bed: its area is the rectangle to the back of the cushions.
        let edge = spec.half_extents() + DVec2::splat(spec.cushion_depth);
        let points = positions(&cloth(&spec));
        let max = points.iter().fold(Vec3::splat(f32::MIN), |a, &p| a.max(p));
        assert!((f64::from(max.x) - edge.x).abs() < 1e-4);
        assert!((f64::from(max.z) - edge.y).abs() < 1e-4);
        let area = triangle_area(&cloth(&spec));
        assert!(
            (area / (4.0 * edge.x * edge.y) - 1.0).abs() < 1e-5,
            "cloth area {area}"
        );
        assert_eq!(positions(&pocket_liners(&spec, 0.1)).len(), 0);
        // The four cushions' noses run corner to corner: the nose line reaches each corner of
        // the playing surface, and at full depth the mitred ends meet on the diagonal.
        let h = spec.half_extents();
        let cushion_points = positions(&cushions(&spec));
        for (sx, sy) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
            let corner = Vec3::new((sx * h.x) as f32, 0.0, -(sy * h.y) as f32);
            let nose = Vec3::new(corner.x, spec.cushion_nose_height as f32, corner.z);
            assert!(cushion_points.iter().any(|p| p.distance(nose) < 1e-5));
        }
        // UMB: the long rail divided into eighths, the short into quarters.
        let diamonds = diamond_positions(&spec);
        assert_eq!(diamonds.len(), 2 * 7 + 2 * 3);
        let on_left: Vec<f64> = diamonds
            .iter()
            .filter(|(rail, _)| *rail == Rail::Left)
            .map(|(_, p)| p.x)
            .collect();
        for (k, x) in on_left.iter().enumerate() {
            assert!((x - spec.length * (k as f64 - 3.0) / 8.0).abs() < 1e-12);
        }
    }

    /// The summed area of a flat mesh's triangles, in square metres.
    fn triangle_area(mesh: &Mesh) -> f64 {
        let points = positions(mesh);
        let Some(bevy::mesh::Indices::U32(indices)) = mesh.indices() else {
            panic!("no u32 indices");
        };
        indices
            .chunks(3)
            .map(|t| {
                let [a, b, c] = [0, 1, 2].map(|k| points[t[k] as usize].as_dvec3());
                (b - a).cross(c - a).length() / 2.0
            })
            .sum()
    }
}
