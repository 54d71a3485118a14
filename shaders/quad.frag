#version 330 core
// Shows the CPU image with nearest filtering and an exact texel-to-pixel mapping.
// Framebuffer pixel (x, yTop), x counting columns from the viewport's left edge and yTop rows
// down from its top (the viewport is the picture's box, which may start right of and above the
// framebuffer's origin), shows texel
//   (floor((x + 0.5) * W / vw), floor((yTop + 0.5) * H / vh))
// of the W x H image, whose row 0 is its top row (uploaded as is, never flipped). The floors are
// computed in integers, so the mapping is exact; texelFetch reads one texel: no filtering.

uniform sampler2D uImage;
uniform ivec2 uViewportOrigin; // the viewport's lower-left corner in framebuffer pixels
uniform ivec2 uViewportSize;   // vw, vh in framebuffer pixels

out vec4 fragColor;

void main() {
    ivec2 size = textureSize(uImage, 0);
    ivec2 inViewport = ivec2(gl_FragCoord.xy) - uViewportOrigin; // pixel centres are at .5
    int x = inViewport.x;
    int yTop = uViewportSize.y - 1 - inViewport.y;
    ivec2 texel = ((2 * ivec2(x, yTop) + 1) * size) / (2 * uViewportSize);
    texel = clamp(texel, ivec2(0), size - 1);
    fragColor = texelFetch(uImage, texel, 0);
}
