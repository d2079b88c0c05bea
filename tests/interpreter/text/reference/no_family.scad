// A fontconfig pattern with no family: OpenSCAD takes fontconfig's best match
// (DejaVu Sans Bold on Debian, whose fontconfig-config pulls in fonts-dejavu-core).
text("Ab&", size = 5, font = ":style=Bold");
