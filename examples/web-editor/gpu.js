// The class scene with mirrors and glass, traced whole on the graphics card
// (WebGL2): drag the picture to orbit the camera, + and − to come closer or
// go back. Click a pixel: its story is worked out again on the CPU, and the
// inspector says where the GPU's colour differs from it. Without WebGL2 the
// picture is traced on the CPU and a line under it says why.
// (Raytracing Sketchbook, global mode.)

function setup() {
  noCanvas(); // the tracer view brings its own canvas

  const eye = new RT.Camera({ width: 160, height: 120, fov: 40, position: [0, 3, 6], pitch: -8 }); // (p5 1.x's friendly errors take a variable named camera for p5's own)
  const view = createTracerView({ scene: RT.classScene({ full: true }), camera: eye, engine: 'gpu' });
  view.orbitDistance = 26; // orbit about the pink glass sphere
  createInspector({ view });
}
