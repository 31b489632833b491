# Prints a Medit mesh of the cube [-1, 1]^3 for scripts/demo.sh: awk -v k=K -f demo_cube.awk
# (k^3 cubes, six positively oriented tetrahedra each about its diagonal: Kuhn's subdivision).
function at(x, y, z) { return (z * (k + 1) + y) * (k + 1) + x + 1 }
function tet(a, b, c, d,   ax, ay, az, m, t) {
  m = (X[b]-X[a]) * ((Y[c]-Y[a]) * (Z[d]-Z[a]) - (Z[c]-Z[a]) * (Y[d]-Y[a])) \
    - (Y[b]-Y[a]) * ((X[c]-X[a]) * (Z[d]-Z[a]) - (Z[c]-Z[a]) * (X[d]-X[a])) \
    + (Z[b]-Z[a]) * ((X[c]-X[a]) * (Y[d]-Y[a]) - (Y[c]-Y[a]) * (X[d]-X[a]))
  if(m < 0) { t = b; b = c; c = t }
  print a, b, c, d, 1
}
BEGIN {
  n = (k + 1) ^ 3
  print "MeshVersionFormatted 1\nDimension 3\nVertices\n" n
  for(z = 0; z <= k; z++) for(y = 0; y <= k; y++) for(x = 0; x <= k; x++) {
    i = at(x, y, z); X[i] = -1 + 2 * x / k; Y[i] = -1 + 2 * y / k; Z[i] = -1 + 2 * z / k
    print X[i], Y[i], Z[i], 0
  }
  print "Tetrahedra\n" 6 * k ^ 3
  for(z = 0; z < k; z++) for(y = 0; y < k; y++) for(x = 0; x < k; x++) {
    a = at(x, y, z); g = at(x + 1, y + 1, z + 1)
    tet(a, at(x + 1, y, z), at(x + 1, y + 1, z), g); tet(a, at(x + 1, y, z), at(x + 1, y, z + 1), g)
    tet(a, at(x, y + 1, z), at(x + 1, y + 1, z), g); tet(a, at(x, y + 1, z), at(x, y + 1, z + 1), g)
    tet(a, at(x, y, z + 1), at(x + 1, y, z + 1), g); tet(a, at(x, y, z + 1), at(x, y + 1, z + 1), g)
  }
  print "End"
}
