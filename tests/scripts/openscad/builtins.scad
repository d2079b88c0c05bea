// OpenSCAD 2021's remaining built-in functions, with its results and
// warnings (openscad -o x.echo); a seeded rands() gives OpenSCAD's values
// (its seed hash, Mersenne twister and uniform distribution).
echo(version = version(), vn = version_num(), version_num() == 20210100, version_num([2019, 5, 0]));
echo(chr(65), chr([72, 105]), chr(65, 66), chr(0), chr(-1), chr(1114112), chr("a"), chr(undef), chr(65.7), chr([65, "x", 66]), chr(256), chr(9731), chr(55296));
echo(ord("A"), ord("☃"), ord(""), ord(65));
echo(lookup(2, [[0, 0], [10, 100]]), lookup(-1, [[0, 0], [10, 100]]), lookup(11, [[0, 0], [10, 100]]), lookup(5, [[10, 1], [0, 0]]), lookup(1, []), lookup(1, [[0, 1], [2]]), lookup(5, [[0, 0], [5, 7], [5, 9], [10, 10]]), lookup(2, [[0, 0], [1, [1]], [3, 3]]));
echo(lookup("a", [[0, 1]]));
echo(search("a", "abcabc"), search("abc", "abcabc"), search("a", "abcabc", 0), search("ab", "abcabc", 0), search("ab", "xabab", 1), search("zz", "abc"));
echo(search(3, [1, 2, 3, 3]), search([3], [1, 2, 3, 3]), search([3], [1, 2, 3, 3], 0), search(3, [[1, "a"], [3, "b"]]), search("b", [[1, "a"], [3, "b"]], 1, 1));
echo(search([1, 5], [[1, "a"], [3, "b"], [1, "c"]], 0), search("x", "abc"), search([[1]], [[1], [2]]), search(undef, [1, 2]), search(1, 5));
echo(search([1, 2, 9], [1, 2, 3, 1]), search([1, 2, 9], [1, 2, 3, 1], 2), search(["a", "q"], [["a", 1], ["q", 2], ["a", 3]], 0), search(2, [[1, 2], [2, 3]], 1, 1));
echo(is_function(1), is_function(undef));
r = rands(0, 1, 3, 42);
echo(len(r), min(r) >= 0, max(r) < 1, r == rands(0, 1, 3, 42), rands(5, 5, 2), len(rands(1, 0, 2, 7)), len(rands(0, 1, 0)), len(rands(0, 1, 2.7)), len(rands(0, 1, -3)), rands(0, 1, "a"));
echo(len(rands(min_value = 0, max_value = 10, value_count = 2, seed_value = 3)));
echo(rands(0, 1, 3, 42), rands(-5, 5, 2, -3.5), rands(10, 20, 2, 1e10), rands(0, 1, 2, 1 / 0), rands(0, 1, 1));
echo(chr([48:57]), chr([70 : 2 : 80]), chr([65, [66, [67], [[68:70]]]]));
// ECHO: version = [2021, 1, 0], vn = 2.02101e+7, true, 2.01905e+7
// ECHO: "A", "Hi", "AB", "", "", "", "", "", "A", "AB", "Ā", "☃", ""
// ECHO: 65, 9731, undef, undef
// ECHO: 20, 0, 100, 0.5, undef, 1, 7, 2
// ECHO: undef
// ECHO: [0], [0, 1, 2], [[0, 3]], [[0, 3], [1, 4]], [1, 2], []
// ECHO: [2], [2], [[2, 3]], [1], [1]
// ECHO: [[0, 2], []], [], [0], undef, []
// ECHO: [0, 1, []], [[0, 3], [1], []], [[0, 2], [1]], [0]
// ECHO: false, false
// ECHO: 3, true, true, true, [5, 5], 2, 0, 2, 3, undef
// ECHO: 2
// ECHO: [0.796543, 0.183435, 0.779691], [-4.7619, -4.2254], [14.1125, 14.5225], [0.0776717, 0.997662], [0.385839]
// ECHO: "0123456789", "FHJLNP", "ABCDEF"
// warning: 6:37: ord() argument 65 is not of type string
// warning: 8:6: lookup("a", ...) first argument is not a number
// warning: 15:170: rands() parameter could not be converted
