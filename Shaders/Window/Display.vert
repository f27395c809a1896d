// One triangle that covers the viewport (the image's rectangle); the fragment shader reads the ray tracer's
// images at its pixel.
#version 460

void main()
{
    vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2)); // (0,0) (2,0) (0,2)
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
