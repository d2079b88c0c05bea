// limits: fuzz
// OpenSCAD asks a < b and then b < a of each element pair: two equal lists
// nested 40 deep took 2^40 steps that way (d = 28: 1.15 s; 40: ~80 min),
// with the step limit charged only after. One three-way comparison per
// pair visits each once.
function n(k) = k == 0 ? 1 : [n(k - 1)];
function m(k) = k == 0 ? 2 : [m(k - 1)];
echo(n(40) < n(40), n(40) > n(40), n(40) <= n(40), n(40) >= n(40), n(40) < m(40), m(40) <= n(40));
// ECHO: false, false, true, true, true, false
