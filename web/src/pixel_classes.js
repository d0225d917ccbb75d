// Pixel classes of a rendered picture, by hue: what the browser test counts to know that
// cloth, arm and the overlays are on screen. Lambert shading scales the channels together
// and the sRGB curve roughly keeps their ratios, so ratio tests separate the cloth's blue,
// the arm's skin tone and the flat overlay colours (red candidate triangles, yellow
// colliding faces, magenta contact points, cyan observers; see COLORS in scene_view.js).

export function classifyPixels({ width, height, pixels }) {
  const counts = {
    total: width * height, background: 0, cloth: 0, arm: 0, red: 0, yellow: 0, magenta: 0,
    cyan: 0, other: 0,
  };
  for (let i = 0; i < pixels.length; i += 4) {
    const r = pixels[i], g = pixels[i + 1], b = pixels[i + 2];
    if (Math.abs(r - 0x26) <= 2 && Math.abs(g - 0x28) <= 2 && Math.abs(b - 0x2c) <= 2) {
      ++counts.background;
    } else if (r >= 150 && g <= 0.25 * r && b <= 0.25 * r) {
      ++counts.red;
    } else if (r >= 150 && g >= 0.7 * r && b <= 0.3 * r) {
      ++counts.yellow;
    } else if (r >= 150 && b >= 150 && g <= 0.3 * r) {
      ++counts.magenta;
    } else if (b >= 150 && g >= 0.8 * b && r <= 0.3 * b) {
      ++counts.cyan;
    } else if (b >= 60 && b > 1.3 * r && b > 1.05 * g) {
      ++counts.cloth;
    } else if (r >= 60 && g > 0.45 * r && g < 0.95 * r && b > 0.3 * r && b < 0.8 * r) {
      ++counts.arm;
    } else {
      ++counts.other;
    }
  }
  return counts;
}
