// A Mesh keeps its good triangles when a few have zero area, and says how many it left out.
import { describe, it, expect } from 'vitest';
import { Ray } from '../../lib/index.js';
import { Mesh } from '../../lib/shapes/mesh.js';

describe('zero-area triangles (real OBJ files and UV spheres have them)', () => {
  const square = [[0, 0, -5], [1, 0, -5], [1, 1, -5], [0, 1, -5], [2, 0, -5]];
  const good = [[0, 1, 2], [0, 2, 3]];

  it('are left out and counted; the good triangles stay, with the same hits', () => {
    const mesh = new Mesh({ positions: square, cells: [good[0], [0, 1, 4], good[1], [1, 1, 2]] }); // a line, and a repeated corner
    expect(mesh.zeroAreaCells).toEqual([1, 3]);
    expect(mesh.triangleCount).toBe(2);
    expect(mesh.cells).toEqual(good);
    const clean = new Mesh({ positions: square, cells: good });
    expect(clean.zeroAreaCells).toEqual([]);
    for (const [x, y] of [[0.2, 0.1], [0.8, 0.9], [0.5, 0.5], [1.5, 0.2]]) {
      const ray = new Ray([x, y, 0], [0, 0, -1]);
      expect(mesh.hit(ray), `${x},${y}`).toBe(clean.hit(ray));
    }
  });

  it('say how many were left out in the mesh\'s record lines (the inspector shows them)', () => {
    const mesh = new Mesh({ positions: square, cells: [good[0], [0, 1, 4], good[1]] });
    const rows = mesh.recordRows(mesh.intersect(new Ray([0.2, 0.1, 0], [0, 0, -1])));
    expect(rows).toContainEqual(['zero-area triangles left out', 1]);
    expect(new Mesh({ positions: square, cells: good }).recordRows(mesh.intersect(new Ray([0.2, 0.1, 0], [0, 0, -1]))).map(([label]) => label))
      .not.toContain('zero-area triangles left out');
  });

  it('a mesh of nothing else is still refused, naming the first cell and how many', () => {
    expect(() => new Mesh({ positions: square, cells: [[0, 1, 4], [1, 1, 2]] })).toThrow(/^cells\[0\]: a, b, c must not lie on one line: the triangle has zero area, as have all 2 triangles$/);
  });

  it('from an OBJ file: a degenerate face among good ones no longer refuses the model', () => {
    const mesh = Mesh.fromOBJ('v 0 0 -5\nv 1 0 -5\nv 1 1 -5\nv 2 0 -5\nf 1 2 3\nf 1 2 4\n');
    expect([mesh.triangleCount, mesh.zeroAreaCells]).toEqual([1, [1]]);
  });
});
