import { it } from 'vitest';
import { REFERENCE_SCENES } from '../reference/scenes';
import { computeReference } from '../reference/softShadowReference';

it('timing', () => {
  for (const scene of REFERENCE_SCENES) {
    let t = performance.now();
    const exact = computeReference(scene);
    const te = performance.now() - t;
    t = performance.now();
    const quad = computeReference(scene, 'exact', { method: 'quadrature', nodes: 16 });
    const tq = performance.now() - t;
    t = performance.now();
    const sampled = computeReference(scene, 'sampled');
    const ts = performance.now() - t;
    let maxS = 0, sumS = 0, n = 0, maxQ = 0, worst = '';
    exact.visibility.forEach((v, l) => {
      for (let i = 0; i < v.length; i++) {
        if (!exact.inRange[i] || exact.ambiguous[i]) continue;
        const ds = Math.abs(v[i] - sampled.visibility[l][i]);
        if (ds > maxS) { maxS = ds; worst = `${i % scene.width},${Math.floor(i / scene.width)} e=${v[i]} s=${sampled.visibility[l][i]}`; }
        sumS += ds; n++;
        maxQ = Math.max(maxQ, Math.abs(v[i] - quad.visibility[l][i]));
      }
    });
    console.log(`${scene.name.padEnd(50)} exact ${te.toFixed(0)}ms quad ${tq.toFixed(0)}ms sampled ${ts.toFixed(0)}ms | vs sampled max ${maxS.toExponential(2)} mean ${(sumS / n).toExponential(2)} (${worst}) | vs quad ${maxQ.toExponential(2)}`);
  }
});
