import { expect, it } from 'vitest';
import { CHECK_PLAYER } from '../../demo/examples/groupCheck';
import { describeLitGroups, type Vec } from './litGroupSuite';

describeLitGroups('Phaser example: lit groups and unlit content', 'phaser/', 'penumbraPhaserGroups', ({ page, read, expectLitSquareInView }) => {
  it('makes a group\'s framebuffer when it is first drawn, keeps it, and frees it when the group leaves the scene or is destroyed', async () => {
    const report = await page().evaluate(() => window.penumbraPhaserGroups!.lifecycle());
    // A framebuffer and its colour texture at least (and a stencil renderbuffer where Phaser asks for one).
    expect(report.made).toBeGreaterThanOrEqual(2);
    expect(report.madeLater).toBe(0);
    expect(report.liveWhenRemoved).toBe(0);
    expect(report.madeWhenAddedBack).toBe(report.made);
    expect(report.liveWhenDestroyed).toBe(0);
    expect(report.glClean).toBe(true);
  });

  it('lights the level and the groups the same when the camera draws through a framebuffer (forceComposite, as camera filters do)', async () => {
    // Floor north, south-west and east of the player, lit by the level's lamps unevenly from top to
    // bottom: lit upside down, they would change by far more than a step.
    const floor: Vec[] = [[700, 220], [650, 400], [880, 230]];
    const onCanvas = await read(CHECK_PLAYER, floor);
    const setComposite = (on: boolean) => page().evaluate((on) => window.penumbraPhaserGroups!.setComposite(on), on);
    await setComposite(true);
    try {
      const composited = await read(CHECK_PLAYER, floor);
      for (const [i, pixel] of composited.read.entries()) {
        for (let k = 0; k < 3; k++) expect(Math.abs(pixel[k] - onCanvas.read[i][k]), `${pixel} vs ${onCanvas.read[i]}`).toBeLessThanOrEqual(1);
      }
      await expectLitSquareInView(CHECK_PLAYER);
    } finally {
      await setComposite(false);
    }
  });
});
