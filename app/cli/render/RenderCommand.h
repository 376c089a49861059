#pragma once

namespace phonglab::cli {

// phonglab render SCENE.json -o OUT.png [--size WxH] [--vertex FILE] [--fragment FILE]
// Renders one frame offscreen and writes an 8-bit RGB PNG.
// Exit 0 on success; 1 on bad input, compile or render failure (no output
// file is written); 2 on wrong arguments.
int runRender(int argc, char **argv);

} // namespace phonglab::cli
