import { expect, it } from 'vitest';
import { describeLitGroups } from './litGroupSuite';

describeLitGroups('PixiJS example: lit groups and unlit content', 'pixi/', 'penumbraPixiGroups', ({ page }) => {
  it('lights a group only while it is in the stage, and draws it in a texture lent by Pixi\'s filter pool', async () => {
    const report = await page().evaluate(() => window.penumbraPixiGroups!.lifecycle());
    // One lighting pass more per frame with the group in the world; none once removed; one again
    // when added back; none once destroyed.
    expect(report.extraPasses).toEqual([1, 0, 1, 0]);
    // Frames drawn with the group make no framebuffer or texture: the group owns none to free.
    expect(report.createdWithGroup).toBe(0);
    expect(report.glClean).toBe(true);
  });
});
