// The page's video files (manual/web.md, "Keep and share"): the WebM muxer of the npm package
// webm-muxer (web/package.json, pinned), bundled by esbuild into one minified script that
// defines the global `OflabWebm` (web/CMakeLists.txt). The frames are encoded by the
// browser's WebCodecs VideoEncoder (web/share.js recordVideo); this only writes them into a
// WebM file, each with the timestamp it is given.
import { Muxer, ArrayBufferTarget } from 'webm-muxer';

window.OflabWebm = { Muxer, ArrayBufferTarget };
