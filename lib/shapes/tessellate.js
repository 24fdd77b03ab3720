/**
 * Triangles for the 3D view of the shapes that are not balls, boxes or
 * planes: `[ax, ay, az, bx, by, bz, cx, cy, cz, …]`, three corners a
 * triangle, counterclockwise seen from outside. The view shades each triangle
 * by its own normal (lib/p5/scene-view/mesh.js, kit.triangles).
 */

/** Sides around the axis of a cylinder or cone in the 3D view. */
const SEGMENTS = 32;

/**
 * A cylinder (topRadius = radius) or a cone (topRadius = 0) about the
 * vertical axis through `center`, `height` tall, with its discs when `capped`.
 * @returns {number[]}
 */
export function axialTriangles(center, radius, topRadius, height, capped) {
  const out = [], y0 = center.y - height / 2, y1 = center.y + height / 2;
  const at = (r, k, y) => [center.x + r * Math.cos((2 * Math.PI * k) / SEGMENTS), y, center.z + r * Math.sin((2 * Math.PI * k) / SEGMENTS)];
  for (let k = 0; k < SEGMENTS; k++) {
    const a = at(radius, k, y0), b = at(radius, k + 1, y0), c = at(topRadius, k + 1, y1), d = at(topRadius, k, y1);
    out.push(...a, ...c, ...b);
    if (topRadius > 0) out.push(...a, ...d, ...c);
    if (!capped) continue;
    out.push(center.x, y0, center.z, ...a, ...b); // the bottom disc, facing down
    if (topRadius > 0) out.push(center.x, y1, center.z, ...c, ...d); // the top disc, facing up
  }
  return out;
}

/**
 * A mesh's triangles from its flat vertices and indices.
 * @param {Float64Array} vertices x, y, z per vertex
 * @param {Int32Array} indices three a triangle
 * @returns {number[]}
 */
export function meshTriangles(vertices, indices) {
  const out = [];
  for (const i of indices) out.push(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]);
  return out;
}
