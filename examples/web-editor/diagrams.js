// One ray, drawn three ways: click a pixel of the picture and the diagrams show
// its ray from the side, the parabola At² + Bt + C whose roots are where the ray
// meets the sphere, and (drag it to turn) the same rays in 3D.
// (Raytracing Sketchbook, global mode: the diagrams draw into the sketch's canvas.)

let view;

function setup() {
  createCanvas(600, 560);
  pixelDensity(1);

  const scene = RT.classScene(); // the class's example: the big pink sphere and its friends
  view = createTracerView({ scene, camera: new RT.Camera({ width: 64, height: 48 }), grid: true });
  createInspector({ view });
  createSceneView({ view, width: 600, height: 400 }); // drag to turn it; the arrow keys too
  view.select(32, 30);
}

function draw() {
  const pixel = view.selected;
  // Not "record": with p5.sound (the editor's 1.x template loads it) that is a p5 function's name.
  const story = pixel && RT.inspectPixel(view.scene, view.camera, pixel.x, pixel.y); // the pixel's whole story
  background('#f6f7f9');
  drawSideView({ scene: view.scene, camera: view.camera, record: story, x: 0, y: 0, w: 600, h: 270 });
  drawParabola({ record: story, x: 0, y: 290, w: 600, h: 270 });
}
