vec3 result;
for (int i = 0; i < 2; i++) result += vec3(1.0);
out vec4 c; void main(){ c += vec4(result, 1.0); }
