// The class's animated example: the yellow, blue and white spheres circle the
// pink one, and every frame is traced whole; the line under the picture counts
// the frames per second. Pause it, then click a pixel of the frame.
// (Raytracing Sketchbook, global mode: draw() moves the animation on.)

let movie;

function setup() {
  noCanvas(); // the tracer view brings its own canvas

  const eye = new RT.Camera({ width: 160, height: 120 }); // the camera (p5 1.x's friendly errors take a variable named camera for p5's own)
  const view = createTracerView({ scene: RT.classSceneAt(0), camera: eye });
  const controls = createDiv().parent(view.figure); // under the picture
  const pauseButton = createButton('Pause').parent(controls).class('rt-button');
  const stats = createSpan('').parent(controls); // frame, FPS, time
  movie = createAnimation({ view, sceneAt: (t) => RT.classSceneAt(t), camera: eye, stats });
  movie.start('main'); // or 'workers': the frames shared out over Web Workers
  pauseButton.mousePressed(() => {
    movie.play(!movie.playing);
    pauseButton.html(movie.playing ? 'Pause' : 'Play');
  });
  createInspector({ view });
}

function draw() {
  movie.tick(deltaTime); // milliseconds since the last frame
}
