// What test/browser/phaserOccluders.test.ts checks in the page beside pixels: where the hulls of
// a tilemap layer and of a sprite go as the objects change, and their life cycle. Made on objects
// of their own, far from the level, and destroyed before returning. Not part of the example.
import Phaser from 'phaser';
import type { Hull, PenumbraPlugin } from 'penumbra-gl/phaser';
import { ART_KEY, PROP_FRAME, WALL_TILE } from './content';

/** A tilemap layer's hulls through its life. */
interface TilemapReport {
  /** Hulls of a 3 × 3 ring of wall tiles, 20 units each, layer at (2000, 3000) scaled 2. */
  ringHulls: number;
  /** Their world bounds `[minX, minY, maxX, maxY]`. */
  ringBounds: number[];
  /** Hulls after putTileAt filled the ring's hole. */
  filledHulls: number;
  /** Whether the hulls of the ring that the fill replaced left the renderer, and the new ones are in it. */
  swappedInRenderer: boolean;
  /** World bounds after the layer moved to (2100, 3050) and its scale became 1. */
  movedBounds: number[];
  /** Whether the layer's hulls left the renderer, and the scene's event listeners are as before, once the layer was destroyed. */
  goneWhenDestroyed: boolean;
}

/** A sprite's hulls through its life. */
interface SpriteReport {
  /** Whether its hulls are in the renderer once added. */
  addedToRenderer: boolean;
  /** Whether they are disabled while the sprite is invisible, and enabled again when it is visible. */
  followVisible: boolean;
  /** Whether they are disabled while the sprite is on no display list, and enabled again when added back. */
  followDisplayList: boolean;
  /** Whether showing another frame replaced them (the old ones out of the renderer, the new ones in). */
  replacedOnFrameChange: boolean;
  /** In a container at (100, 50) turned a quarter and scaled 2, a sprite at (10, 0): its hulls' position, rotation and x scale. */
  inContainer: number[];
  /** Whether its hulls left the renderer, the listeners are as before and the plugin forgot it once the sprite was destroyed. */
  goneWhenDestroyed: boolean;
}

/** `window.penumbraPhaserOccluders`. */
interface OccluderCheckHook {
  tilemap(): TilemapReport;
  sprite(): SpriteReport;
}

declare global {
  interface Window {
    penumbraPhaserOccluders?: OccluderCheckHook;
  }
}

/** World bounds of hulls, from their points and transforms. */
function worldBounds(hulls: readonly Hull[]): number[] {
  const bounds = [Infinity, Infinity, -Infinity, -Infinity];
  for (const hull of hulls) {
    const cos = Math.cos(hull.rotation), sin = Math.sin(hull.rotation);
    for (const [px, py] of hull.points) {
      const lx = (px - hull.origin[0]) * hull.scale[0], ly = (py - hull.origin[1]) * hull.scale[1];
      const x = hull.position[0] + lx * cos - ly * sin, y = hull.position[1] + lx * sin + ly * cos;
      bounds[0] = Math.min(bounds[0], x);
      bounds[1] = Math.min(bounds[1], y);
      bounds[2] = Math.max(bounds[2], x);
      bounds[3] = Math.max(bounds[3], y);
    }
  }
  return bounds;
}

/** Installs `window.penumbraPhaserOccluders` for a scene running the plugin as `penumbra`. */
export function installOccluderCheck(scene: Phaser.Scene & { penumbra: PenumbraPlugin }): void {
  const listeners = () => ['prerender', 'shutdown'].map((name) => scene.sys.events.listenerCount(name)).join();
  const inRenderer = (hulls: readonly Hull[]) => hulls.every((hull) => scene.penumbra.penumbra.hulls.includes(hull));
  const outOfRenderer = (hulls: readonly Hull[]) => hulls.every((hull) => !scene.penumbra.penumbra.hulls.includes(hull));

  window.penumbraPhaserOccluders = {
    tilemap: () => {
      const before = listeners();
      const map = scene.make.tilemap({ data: [[WALL_TILE, WALL_TILE, WALL_TILE], [WALL_TILE, -1, WALL_TILE], [WALL_TILE, WALL_TILE, WALL_TILE]], tileWidth: 20, tileHeight: 20 });
      const tileset = map.addTilesetImage(ART_KEY, ART_KEY, 20, 20)!;
      const layer = (map.createLayer(0, tileset, 2000, 3000) as Phaser.Tilemaps.TilemapLayer).setScale(2).setCollision(WALL_TILE);
      const walls = scene.penumbra.addTilemapLayer(layer);
      const ring = walls.hulls;
      const ringBounds = worldBounds(ring);
      layer.putTileAt(WALL_TILE, 1, 1);
      walls.update();
      const filled = walls.hulls;
      const swappedInRenderer = outOfRenderer(ring) && inRenderer(filled);
      layer.setPosition(2100, 3050).setScale(1);
      walls.update();
      const movedBounds = worldBounds(walls.hulls);
      const last = walls.hulls;
      map.destroy();
      return {
        ringHulls: ring.length, ringBounds, filledHulls: filled.length, swappedInRenderer, movedBounds,
        goneWhenDestroyed: walls.isDestroyed && outOfRenderer(last) && listeners() === before,
      };
    },
    sprite: () => {
      const before = listeners();
      const sprite = scene.add.sprite(2000, 2000, ART_KEY, PROP_FRAME);
      const shadow = scene.penumbra.addSprite(sprite);
      const first = shadow.hulls;
      const enabled = () => shadow.hulls.every((hull) => hull.enabled);
      const disabled = () => shadow.hulls.every((hull) => !hull.enabled);
      const addedToRenderer = first.length > 0 && inRenderer(first);

      sprite.setVisible(false);
      shadow.update();
      const hidden = disabled();
      sprite.setVisible(true);
      shadow.update();
      const followVisible = hidden && enabled();

      scene.children.remove(sprite);
      shadow.update();
      const off = disabled();
      scene.add.existing(sprite);
      shadow.update();
      const followDisplayList = off && enabled();

      sprite.setFrame('__BASE');
      shadow.update();
      const replacedOnFrameChange = shadow.hulls.length > 0 && shadow.hulls.every((hull) => !first.includes(hull))
        && outOfRenderer(first) && inRenderer(shadow.hulls);

      const container = scene.add.container(100, 50).setRotation(Math.PI / 2).setScale(2);
      container.add(sprite.setFrame(PROP_FRAME).setPosition(10, 0));
      shadow.update();
      const [hull] = shadow.hulls;
      const inContainer = [hull.position[0], hull.position[1], hull.rotation, hull.scale[0]];

      const last = shadow.hulls;
      container.destroy();
      return {
        addedToRenderer, followVisible, followDisplayList, replacedOnFrameChange, inContainer,
        goneWhenDestroyed: shadow.isDestroyed && outOfRenderer(last) && listeners() === before && !scene.penumbra.removeSprite(sprite),
      };
    },
  };
}
