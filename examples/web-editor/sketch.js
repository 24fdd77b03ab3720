// A ray from the eye through each pixel: the first sphere it hits gives the
// pixel its colour. Click a pixel to see its ray, A, B, C, the discriminant
// and its angles; the arrow keys move the selected pixel.
// (Raytracing Sketchbook, global mode: RT.… makes the scene, createTracerView traces it.)

function setup() {
  noCanvas(); // the tracer view brings its own canvas

  const scene = new RT.Scene({ background: [0.85, 0.92, 1], ambient: 0.1 });
  scene.add(new RT.Sphere([0, 0, -20], 4, { color: [1, 0.32, 0.36] })); // center, radius, material
  scene.add(new RT.Sphere([6, 1, -26], 2, { color: [0.3, 0.6, 1] }));
  scene.add(new RT.PointLight([-10, 20, 0]));                            // position

  const camera = new RT.Camera({ width: 64, height: 48, fov: 30 }); // looks toward −z
  const view = createTracerView({ scene, camera, grid: true });
  createInspector({ view }); // click a pixel: its whole story
}
