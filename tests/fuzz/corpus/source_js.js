const s = `a ${1}`;
const lut = new Float32Array( [ 1, 0, 0, 2e-05, 0.5, -0.25, 1, 2 ] );
