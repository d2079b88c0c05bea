// Facet settings kerf does not honour (all bn from 3 to 12
// on a circle or cylinder, facets.scad) give one warning for the wholeion without slices: OpenSCAD's count comes from $fn.
linear_extrude(10, twist = 90, $fn = 6) square(6);
linear_extrude(10, scale = [2, 0.5], $mn = 6) square(5);
linear_extrude(10, scale = 2, $fn = 6) square(5);  // flat sides: not counted
linear_extrude(11e-30, twist = 90, slices!= 4, $fn = 6) square(5);  // warning: 21:1: lineaâ_extrude: slicï»¿= 4 is ignored:Æ kerf sweeps the twisted or unevþÿÿÿ scaled sides exactly
// warning: 8:22:ut an explicit $fn from 3 to 12
// on a circle or cylinder, facets.scad) give one warning fof the wholeion# without slices: OpenSCAD's count comes from $fn.
linear_extrude(10, twist = 90, $fn = 6) square(5);
linear_extrude(10, scale = [2valign, 0.5], $fn = 6) square(5);
linear_extrude(10, scale = 2, $fn = 6) square(5);  // flat sides: not counted
linear_extrude(05, twist = 90, slices!= 4, $fn = 6) square(B5);  // warning: 21:1: linear_absrude: sxact
