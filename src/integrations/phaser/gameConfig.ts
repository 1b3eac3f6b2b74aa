import Phaser from 'phaser';
import { isWebGL2, notWebGL2Error } from '../../gl/capabilities';
import { describe } from './shared';

/**
 * What {@link PenumbraPlugin} says when Phaser's context is not WebGL2: Phaser 4 asks its canvas
 * for a WebGL1 context unless the game config gives it one. @internal
 */
export const PHASER_WEBGL2_FIX = 'Phaser 4 makes a WebGL1 context unless its game config gives one; '
  + 'make the game with new Phaser.Game(penumbraGameConfig({ … })), penumbraGameConfig from \'penumbra-gl/phaser\'';

/** The fields of Phaser's parsed config that the context is made from and set into. */
interface BootConfig {
  renderType: number;
  canvas: HTMLCanvasElement | null;
  context: unknown;
  transparent: boolean;
  desynchronized: boolean;
  antialiasGL: boolean;
  premultipliedAlpha: boolean;
  stencil: boolean;
  failIfMajorPerformanceCaveat: boolean;
  powerPreference: string;
  preserveDrawingBuffer: boolean;
}

/**
 * Returns `config` made to give Phaser a WebGL2 context, which {@link PenumbraPlugin} needs:
 * Phaser 4 asks its canvas for a WebGL1 context unless its config gives it one. Everything else in
 * `config` is kept (it is not changed itself).
 *
 * ```ts
 * new Phaser.Game(penumbraGameConfig({
 *   width: 800, height: 600, scene: Level,
 *   plugins: { scene: [{ key: 'PenumbraPlugin', plugin: PenumbraPlugin, mapping: 'penumbra' }] },
 * }));
 * ```
 *
 * The context is made when the game boots (in `callbacks.preBoot`, before your own `preBoot`), on
 * `config.canvas` or a new canvas, with the attributes Phaser itself would ask for (from
 * `transparent`, `antialiasGL`, `premultipliedAlpha`, `stencil`, `preserveDrawingBuffer`,
 * `powerPreference`, `failIfMajorPerformanceCaveat`, `desynchronized`), but for one: with
 * `antialiasGL` (Phaser's default) the canvas has an alpha channel, as the lighting can copy a
 * multisampled canvas only into a target of the same RGBA format; Phaser still clears it opaque
 * unless `transparent`. `type` becomes `Phaser.WEBGL`. A `config.context` of your own is kept when
 * it is WebGL2 (make it with `antialias: false` or `alpha: true`).
 *
 * Without WebGL2 in the browser the game does not boot: the error thrown names the cause.
 * @throws TypeError for a `type` other than `Phaser.AUTO` or `Phaser.WEBGL`, or a `context` that
 * is not WebGL2.
 */
export function penumbraGameConfig(config: Phaser.Types.Core.GameConfig = {}): Phaser.Types.Core.GameConfig {
  if (typeof config !== 'object' || config === null) throw new TypeError(`penumbra: penumbraGameConfig takes a Phaser game config object, got ${describe(config)}`);
  const { type } = config;
  if (type !== undefined && type !== Phaser.AUTO && type !== Phaser.WEBGL) {
    throw new TypeError(`penumbra: penumbraGameConfig: the lighting needs Phaser's WebGL renderer, got type ${describe(type)} (use Phaser.WEBGL or leave it out)`);
  }
  if (config.context !== undefined) {
    if (!isWebGL2(config.context)) throw notWebGL2Error('penumbraGameConfig: config.context', config.context, 'pass canvas.getContext(\'webgl2\'), or leave context out');
    const canvas = config.canvas ?? (config.context as unknown as WebGL2RenderingContext).canvas as HTMLCanvasElement;
    return { ...config, type: Phaser.WEBGL, canvas };
  }
  const ownPreBoot = config.callbacks?.preBoot;
  return {
    ...config,
    type: Phaser.WEBGL,
    callbacks: {
      ...config.callbacks,
      preBoot: (game: Phaser.Game) => {
        giveWebGL2Context(game.config);
        ownPreBoot?.(game);
      },
    },
  };
}

/** Makes the WebGL2 context on the configured canvas or a new one, as Phaser's WebGLRenderer would make its own. */
function giveWebGL2Context(config: BootConfig): void {
  const canvas = config.canvas ?? document.createElement('canvas');
  const context = canvas.getContext('webgl2', {
    // The lighting copies the canvas with blitFramebuffer, which from a multisampled buffer needs
    // the same format as its RGBA target: an antialiased canvas gets an alpha channel, which
    // Phaser still clears opaque unless the game is transparent.
    alpha: config.transparent || config.antialiasGL,
    desynchronized: config.desynchronized,
    depth: true,
    antialias: config.antialiasGL,
    premultipliedAlpha: config.premultipliedAlpha,
    stencil: config.stencil,
    failIfMajorPerformanceCaveat: config.failIfMajorPerformanceCaveat,
    powerPreference: config.powerPreference as WebGLPowerPreference,
    preserveDrawingBuffer: config.preserveDrawingBuffer,
  });
  if (!context) {
    throw new Error('penumbra: penumbraGameConfig: canvas.getContext(\'webgl2\') gave no context: this browser has no WebGL2 '
      + '(penumbra-gl needs it), or the canvas given as config.canvas already has another kind of context');
  }
  config.canvas = canvas;
  config.context = context;
  config.renderType = Phaser.WEBGL;
}
