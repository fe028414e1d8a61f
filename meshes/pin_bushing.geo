// The pin–bushing model of one revolute clearance joint, for round (unworn) profiles:
// the user-editable form of what src/fe/pin_bushing_mesher.cc builds through the gmsh
// C++ API (which also takes worn profiles, sample by sample). Same construction:
//   - the pin: an annulus between a rigid core circle (through which it is loaded) and
//     its contact surface, a closed curve through N profile samples split into four
//     splines (quarter turns) with a uniform (transfinite) node spacing;
//   - the bushing: a ring between the bore (the same kind of curve) and a fixed outer
//     circle;
//   - element size h at both contact surfaces, kept within a layer of thickness t, then
//     growing linearly with the distance from them up to H (Distance + Threshold);
//   - quadrilaterals: Frontal-Delaunay, Blossom recombination, then every element split
//     into quadrilaterals — the split halves all sizes, so the curves are meshed at
//     twice the target sizes;
//   - physical groups named "MaterialID:n" / "BoundaryID:n" with the ids of
//     src/fe/boundary_ids.h, which deal.II's GridIn::read_msh turns into material and
//     boundary ids.
// Both bodies are in their own frame, centred at the joint centre; at zero eccentricity
// the pin lies inside the bore, so one mesh holds both (the contact kinematics of a
// load state are applied by the solver, not by the mesh).
//
// Mesh it by hand (lengths in metres):
//   gmsh -2 meshes/pin_bushing.geo -o pin_bushing.msh
//   gmsh -2 meshes/pin_bushing.geo -setnumber surface_size 1e-4 -setnumber max_size 2e-3 -o coarse.msh
// The defaults are the geometry of params/pin_bushing.prm (steel pin in a steel
// bushing, 0.5 mm radial clearance) with the FE model's default sizes and the whole
// circumference refined, as a wear loop meshes it. The test
// tests/unit/fe/geo_mesh_test.cc meshes this file and the C++ mesher side by side and
// compares their statistics.

DefineConstant[ bore_radius = 0.012 ];       // R1 [m]
DefineConstant[ pin_radius = 0.0115 ];       // R2 [m]
DefineConstant[ core_fraction = 0.4 ];       // rigid core radius / pin radius [-]
DefineConstant[ outer_radius = 0.024 ];      // fixed outer edge of the bushing [m]
DefineConstant[ n_points = 360 ];            // profile samples per surface [-]
DefineConstant[ surface_size = 25e-6 ];      // element size at the contact surfaces [m]
DefineConstant[ max_size = 1.5e-3 ];         // element size far from them [m]
DefineConstant[ growth = 0.3 ];              // dh/dd away from the surfaces [-]
DefineConstant[ layer = 0.1e-3 ];            // depth kept at the surface size [m]

core_radius = core_fraction * pin_radius;
h = 2 * surface_size; // curves are meshed at twice the sizes (see the split above)
H = 2 * max_size;

// A closed profile curve of radius r through n_points samples, as four splines with
// uniform spacing ≈ h (segments from the polyline length of a quarter, as the C++
// mesher computes them). Sets curves[] and segments.
Macro MakeProfile
  first_point = newp;
  For k In {0 : n_points - 1}
    Point(first_point + k) = {r * Cos(2 * Pi * k / n_points), r * Sin(2 * Pi * k / n_points), 0, h};
  EndFor
  quarter_length = (n_points / 4) * 2 * r * Sin(Pi / n_points);
  segments = Round(quarter_length / h);
  If (segments < 2)
    segments = 2;
  EndIf
  curves[] = {};
  For q In {0 : 3}
    sample_points[] = {};
    For k In {(q * n_points) / 4 : ((q + 1) * n_points) / 4}
      sample_points[] += {first_point + (k % n_points)};
    EndFor
    c = newc;
    Spline(c) = sample_points[];
    Transfinite Curve {c} = segments + 1;
    curves[] += {c};
  EndFor
Return

// A circle of radius r about the origin as four arcs, mesh size H. Sets arcs[].
Macro MakeCircle
  centre = newp;
  Point(centre) = {0, 0, 0, H};
  For q In {0 : 3}
    Point(centre + 1 + q) = {r * Cos(q * Pi / 2), r * Sin(q * Pi / 2), 0, H};
  EndFor
  arcs[] = {};
  For q In {0 : 3}
    c = newc;
    Circle(c) = {centre + 1 + q, centre, centre + 1 + ((q + 1) % 4)};
    arcs[] += {c};
  EndFor
Return

// Pin annulus: surface loop and rigid-core hole.
r = pin_radius;
Call MakeProfile;
pin_curves[] = curves[];
pin_segments = segments;
r = core_radius;
Call MakeCircle;
core_curves[] = arcs[];
pin_loop = newll;
Curve Loop(pin_loop) = pin_curves[];
core_loop = newll;
Curve Loop(core_loop) = core_curves[];
pin_area = news;
Plane Surface(pin_area) = {pin_loop, core_loop};

// Bushing ring: fixed outer circle and the bore as its hole.
r = bore_radius;
Call MakeProfile;
bore_curves[] = curves[];
bore_segments = segments;
r = outer_radius;
Call MakeCircle;
outer_curves[] = arcs[];
outer_loop = newll;
Curve Loop(outer_loop) = outer_curves[];
bore_loop = newll;
Curve Loop(bore_loop) = bore_curves[];
ring_area = news;
Plane Surface(ring_area) = {outer_loop, bore_loop};

// Material and boundary ids of src/fe/boundary_ids.h.
Physical Surface("MaterialID:1") = {pin_area};
Physical Surface("MaterialID:2") = {ring_area};
Physical Curve("BoundaryID:1") = core_curves[];
Physical Curve("BoundaryID:2") = pin_curves[];
Physical Curve("BoundaryID:3") = bore_curves[];
Physical Curve("BoundaryID:4") = outer_curves[];

// Element size: h within the layer below both contact surfaces, then growing linearly
// with the distance d from them, h(d) = min(h + growth (d − t), H).
Field[1] = Distance;
Field[1].CurvesList = {pin_curves[], bore_curves[]};
Field[1].NumPointsPerCurve = (pin_segments > bore_segments ? 4 * pin_segments : 4 * bore_segments) + 10;
Field[2] = Threshold;
Field[2].IField = 1;
Field[2].LcMin = h;
Field[2].LcMax = H;
Field[2].DistMin = layer;
dist_span = (H - h) / (2 * growth);
If (dist_span < h)
  dist_span = h;
EndIf
Field[2].DistMax = layer + dist_span;
Background Field = 2;

Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;               // Frontal-Delaunay
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // Blossom
Mesh.SubdivisionAlgorithm = 1;    // all quadrilaterals
Mesh.MshFileVersion = 4.1;
