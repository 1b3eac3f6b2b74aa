import { describe, expect, it } from 'vitest';
import { Hull, PointLight, Spotlight, TexturedLight } from '../../src/index';

/**
 * The rule for vectors handed out by getters: each is a frozen snapshot. Writing into it throws
 * (modules are strict code) and changes nothing; later changes give a new array and leave the
 * old one as it was; reading the same value twice gives the same array, so reading allocates nothing.
 */
function expectFrozenSnapshot(read: () => readonly number[]): void {
  const before = read();
  expect(Object.isFrozen(before)).toBe(true);
  expect(read()).toBe(before);
  const copy = [...before];
  expect(() => { (before as number[])[0] = -5; }).toThrow(TypeError);
  expect(() => { (before as number[]).push(1); }).toThrow(TypeError);
  expect(read()).toEqual(copy);
}

const texture = {} as WebGLTexture;
const square: [number, number][] = [[0, 0], [10, 0], [10, 10], [0, 10]];

describe('getters hand out frozen snapshots', () => {
  it.each([
    ['PointLight', () => new PointLight({ position: [1, 2], color: [0.5, 0.5, 0.5] })],
    ['Spotlight', () => new Spotlight({ position: [1, 2] })],
    ['TexturedLight', () => new TexturedLight({ texture, size: [4, 5] })],
  ])('%s: position, origin and color', (_name, make) => {
    const light = make();
    expectFrozenSnapshot(() => light.position);
    expectFrozenSnapshot(() => light.origin);
    expectFrozenSnapshot(() => light.color);
  });

  it('TexturedLight: size, given or following the range', () => {
    const light = new TexturedLight({ texture, size: [4, 5] });
    expectFrozenSnapshot(() => light.size);
    const following = new TexturedLight({ texture, range: 3 });
    expect(Object.isFrozen(following.size)).toBe(true);
    expect(following.size).toEqual([6, 6]);
  });

  it('Hull: points (and each pair), position, origin and scale', () => {
    const hull = new Hull(square, { position: [5, 5], scale: [2, 3] });
    expectFrozenSnapshot(() => hull.position);
    expectFrozenSnapshot(() => hull.origin);
    expectFrozenSnapshot(() => hull.scale);
    expect(Object.isFrozen(hull.points)).toBe(true);
    expectFrozenSnapshot(() => hull.points[1]);
  });

  it('a write through a getter cannot leave a stale shadow: the hull neither moves nor changes version', () => {
    const hull = new Hull(square, { position: [5, 5] });
    hull.updateWorld();
    const version = hull.version;
    expect(() => { (hull.position as unknown as number[])[0] += 20; }).toThrow(TypeError);
    expect(hull.version).toBe(version);
    expect(hull.position).toEqual([5, 5]);
    expect(hull.worldBounds[0]).toBe(5);
  });

  it('a snapshot keeps its values after the property changes; the getter then returns the new value', () => {
    const light = new PointLight({ position: [1, 2] });
    const old = light.position;
    light.setPosition(3, 4);
    expect(old).toEqual([1, 2]);
    expect(light.position).toEqual([3, 4]);
    const hull = new Hull(square);
    const oldScale = hull.scale;
    hull.scale = 2;
    expect(oldScale).toEqual([1, 1]);
    expect(hull.scale).toEqual([2, 2]);
  });

  it('a rejected assignment changes no component', () => {
    const light = new PointLight({ position: [1, 2], color: [1, 1, 1] });
    expect(() => { light.position = [5, NaN]; }).toThrow(RangeError);
    expect(() => { light.color = [0.5, 0.5, -1]; }).toThrow(RangeError);
    expect(light.position).toEqual([1, 2]);
    expect(light.color).toEqual([1, 1, 1]);
  });
});
