'use strict';
// Minimal PNG reading and writing for the browser tests (no packages): 8-bit RGB or RGBA,
// not interlaced, which is what Chromium's screenshots are. Images are
// {width, height, data: Uint8Array RGBA}.
const zlib = require('zlib');

const kSignature = Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]);

function paeth(a, b, c) {
  const p = a + b - c;
  const pa = Math.abs(p - a);
  const pb = Math.abs(p - b);
  const pc = Math.abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// Decodes `bytes` (a Buffer); throws Error naming `origin` for anything else.
function decodePng(bytes, origin) {
  if (bytes.length < 8 || !bytes.subarray(0, 8).equals(kSignature)) throw new Error(`${origin}: not a PNG file`);
  let at = 8;
  let header = null;
  const idat = [];
  while (at + 8 <= bytes.length) {
    const length = bytes.readUInt32BE(at);
    const type = bytes.toString('latin1', at + 4, at + 8);
    const body = bytes.subarray(at + 8, at + 8 + length);
    if (type === 'IHDR') {
      header = { width: body.readUInt32BE(0), height: body.readUInt32BE(4), depth: body[8], colour: body[9], interlace: body[12] };
    } else if (type === 'IDAT') {
      idat.push(body);
    } else if (type === 'IEND') {
      break;
    }
    at += 12 + length;
  }
  if (!header || header.depth !== 8 || ![2, 6].includes(header.colour) || header.interlace !== 0) {
    throw new Error(`${origin}: only 8-bit RGB or RGBA PNG without interlacing is read`);
  }
  const channels = header.colour === 6 ? 4 : 3;
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = header.width * channels;
  if (raw.length < header.height * (stride + 1)) throw new Error(`${origin}: truncated image data`);
  const rows = Buffer.alloc(header.height * stride);
  for (let y = 0; y < header.height; ++y) {
    const filter = raw[y * (stride + 1)];
    const src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const row = rows.subarray(y * stride, (y + 1) * stride);
    const up = y > 0 ? rows.subarray((y - 1) * stride, y * stride) : Buffer.alloc(stride);
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? row[i - channels] : 0;
      const c = i >= channels ? up[i - channels] : 0;
      const x = src[i];
      const predicted = [0, a, up[i], (a + up[i]) >> 1, paeth(a, up[i], c)][filter];
      if (predicted === undefined) throw new Error(`${origin}: unknown PNG filter ${filter}`);
      row[i] = (x + predicted) & 255;
    }
  }
  const data = new Uint8Array(header.width * header.height * 4);
  for (let p = 0; p < header.width * header.height; ++p) {
    for (let c = 0; c < 3; ++c) data[4 * p + c] = rows[p * channels + c];
    data[4 * p + 3] = channels === 4 ? rows[p * channels + 3] : 255;
  }
  return { width: header.width, height: header.height, data };
}

module.exports = { decodePng };
