#version 330 core
// The quarter-res passes' cover (QuarterResPath::ScreenTiles): rectangles of screen tiles, given
// in full-resolution pixels, so the same vertices cover the full-size and the half-size targets
// (the viewport is the bound target's). The fragment shaders work from gl_FragCoord.
layout(location = 0) in vec2 aPixel;
uniform vec2 uViewSize;  // full-resolution view size in pixels

void main() {
    gl_Position = vec4(aPixel / uViewSize * 2.0 - 1.0, 0.0, 1.0);
}
