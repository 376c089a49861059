uniform float a;//@range 0 1
uniform sampler2D tex;
uniform float b[0x10]; // @step
