// The accuracy mask's pixel rule, shared by both line methods' fragment stages: a pixel is
// on the line when the visible spine passes through its unit square.

// True when segment a-b passes through the unit pixel square centred on c
// (separating axes: x, y and the segment's normal).
bool crosses_pixel(vec2 c, vec2 a, vec2 b) {
    vec2 lo = min(a, b), hi = max(a, b);
    if (hi.x < c.x - 0.5 || lo.x >= c.x + 0.5 || hi.y < c.y - 0.5 || lo.y >= c.y + 0.5) return false;
    vec2 d = b - a;
    vec2 n = vec2(-d.y, d.x);
    return abs(dot(n, c - a)) <= 0.5 * (abs(n.x) + abs(n.y));
}
