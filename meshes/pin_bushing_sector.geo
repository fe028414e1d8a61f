// The periodic pin–bushing mesh of round profiles, as src/fe/pin_bushing_mesher.cc
// builds it for the wear loop's fresh joints and the fe law's round tables: each body
// is K identical sectors, so that its compliance is the same in every sector (the
// solver computes one sector's influence columns instead of every one). This file is
// the two sectors that gmsh meshes — the pin's (rigid core to contact surface) and the
// bushing's (bore to fixed outer edge); the C++ mesher writes K copies of each, rotated
// by 2π k/K, with the nodes of the shared radial edges merged (the radial edge at 2π/K
// is a periodic copy of the one at 0, so the copies fit). Same sizes as
// meshes/pin_bushing.geo:
//   - the contact arc of each sector transfinite with sector_elements / 2 segments
//     (split in two at the end), K = 2πR / (sector_elements × surface_size) rounded,
//     at least 4;
//   - element size h within the layer of thickness t below the contact arcs, growing
//     linearly with the distance from them up to H (Distance + Threshold);
//   - quadrilaterals: Frontal-Delaunay, Blossom recombination, every element split.
// The test tests/unit/fe/geo_mesh_test.cc (GeoMesh.SectorGeoFileIsWhatThePeriodicMesherCopies)
// meshes this file and requires the C++ mesher's counts to be K times its sectors'.
//
//   gmsh -2 meshes/pin_bushing_sector.geo -o sectors.msh

DefineConstant[ bore_radius = 0.012 ];       // R1 [m]
DefineConstant[ pin_radius = 0.0115 ];       // R2 [m]
DefineConstant[ core_fraction = 0.4 ];       // rigid core radius / pin radius [-]
DefineConstant[ outer_radius = 0.024 ];      // fixed outer edge of the bushing [m]
DefineConstant[ surface_size = 25e-6 ];      // element size at the contact surfaces [m]
DefineConstant[ max_size = 1.5e-3 ];         // element size far from them [m]
DefineConstant[ growth = 0.3 ];              // dh/dd away from the surfaces [-]
DefineConstant[ layer = 0.1e-3 ];            // depth kept at the surface size [m]
sector_elements = 32;                        // contact-surface elements per sector (fixed)

core_radius = core_fraction * pin_radius;
h = 2 * surface_size; // curves are meshed at twice the sizes (see the split above)
H = 2 * max_size;

// One annular sector inner ≤ r ≤ outer, 0 ≤ θ ≤ 2π/K, K from the contact radius; its
// contact arc is the outer one if contact_outside, else the inner one. Sets surface,
// contact, far and K.
Macro Sector
  contact_radius = contact_outside ? outer : inner;
  K = Round(2 * Pi * contact_radius / (sector_elements * surface_size));
  If (K < 4)
    K = 4;
  EndIf
  a = 2 * Pi / K;
  hi = contact_outside ? H : h;
  ho = contact_outside ? h : H;
  centre = newp;
  Point(centre) = {0, 0, 0, H};
  i0 = newp;
  Point(i0) = {inner, 0, 0, hi};
  i1 = newp;
  Point(i1) = {inner * Cos(a), inner * Sin(a), 0, hi};
  o0 = newp;
  Point(o0) = {outer, 0, 0, ho};
  o1 = newp;
  Point(o1) = {outer * Cos(a), outer * Sin(a), 0, ho};
  left = newc;
  Line(left) = {i0, o0};
  right = newc;
  Line(right) = {i1, o1};
  inner_arc = newc;
  Circle(inner_arc) = {i0, centre, i1};
  outer_arc = newc;
  Circle(outer_arc) = {o0, centre, o1};
  loop = newll;
  Curve Loop(loop) = {left, outer_arc, -right, -inner_arc};
  surface = news;
  Plane Surface(surface) = {loop};
  contact = contact_outside ? outer_arc : inner_arc;
  far = contact_outside ? inner_arc : outer_arc;
  Transfinite Curve {contact} = sector_elements / 2 + 1;
  Periodic Curve {right} = {left} Rotate {{0, 0, 1}, {0, 0, 0}, a};
Return

inner = core_radius;
outer = pin_radius;
contact_outside = 1;
Call Sector;
pin_area = surface;
pin_contact = contact;
pin_core = far;
pin_sectors = K;

inner = bore_radius;
outer = outer_radius;
contact_outside = 0;
Call Sector;
ring_area = surface;
bore_contact = contact;
ring_outer = far;
bore_sectors = K;

// Material and boundary ids of src/fe/boundary_ids.h (for the sectors).
Physical Surface("MaterialID:1") = {pin_area};
Physical Surface("MaterialID:2") = {ring_area};
Physical Curve("BoundaryID:1") = {pin_core};
Physical Curve("BoundaryID:2") = {pin_contact};
Physical Curve("BoundaryID:3") = {bore_contact};
Physical Curve("BoundaryID:4") = {ring_outer};

// Element size from the distance to the contact arcs.
Field[1] = Distance;
Field[1].CurvesList = {pin_contact, bore_contact};
Field[1].NumPointsPerCurve = 4 * sector_elements;
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
Mesh.Algorithm = 6;              // Frontal-Delaunay
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1; // Blossom
Mesh.SubdivisionAlgorithm = 1;   // every element split into quadrilaterals
Mesh.MshFileVersion = 4.1;
