# Prints an OBJ (z = 0) of the unit square's n x n grid, two triangles a cell:
#   awk -v n=N -v start=MODE -f lshape_grid.awk
# start=source: the grid itself. Any other MODE: the grid's border put on the L-shaped domain
# [0, 1]^2 minus [0.5, 1]^2 by arc length (both perimeters are 4; the square's corner (1, 1) goes to
# the L's inner corner), its inside vertices at
#   grid:      their own places (the triangles over the missing quarter fold back into the L);
#   mirrored:  their places mirrored about the diagonal x = y (every triangle off the border inverted);
#   random:    uniform random points of [0, 1]^2 (a fixed Park-Miller sequence: the same on every awk);
#   collapsed: one point, (0.25, 0.25) (every triangle off the border flat).
# The untangling benchmark of bench_untangle.sh maps the grid onto the L from each start, border fixed.
function l_shape(t) {   # the point of the L's border at arc length t from (0, 0), counter-clockwise
  if(t < 1) { X = t; Y = 0 }
  else if(t < 1.5) { X = 1; Y = t - 1 }
  else if(t < 2) { X = 1 - (t - 1.5); Y = 0.5 }
  else if(t < 2.5) { X = 0.5; Y = 0.5 + (t - 2) }
  else if(t < 3) { X = 0.5 - (t - 2.5); Y = 1 }
  else { X = 0; Y = 1 - (t - 3) }
}
function uniform() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
BEGIN {
  seed = 12345
  for(j = 0; j <= n; j++)
    for(i = 0; i <= n; i++) {
      x = i / n; y = j / n
      if(start != "source") {
        if(j == 0) { l_shape(x); x = X; y = Y }
        else if(i == n) { l_shape(1 + y); x = X; y = Y }
        else if(j == n) { l_shape(3 - x); x = X; y = Y }
        else if(i == 0) { l_shape(4 - y); x = X; y = Y }
        else if(start == "mirrored") { t = x; x = y; y = t }
        else if(start == "random") { x = uniform(); y = uniform() }
        else if(start == "collapsed") { x = 0.25; y = 0.25 }
        else if(start != "grid") { print "unknown start " start > "/dev/stderr"; exit 2 }
      }
      printf "v %.17g %.17g 0\n", x, y
    }
  for(j = 0; j < n; j++)
    for(i = 0; i < n; i++) {
      a = j * (n + 1) + i + 1; b = a + 1; c = a + n + 1; d = c + 1
      print "f", a, b, d
      print "f", a, d, c
    }
}
