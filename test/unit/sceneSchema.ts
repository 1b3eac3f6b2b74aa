import { readFileSync } from 'node:fs';
import Ajv from 'ajv';

/** The scene format's JSON Schema as the package ships it. */
export const SCENE_SCHEMA = JSON.parse(readFileSync(new URL('../../schema/scene.schema.json', import.meta.url), 'utf8'));

// Strict: a keyword the schema misspells or misplaces is an error, not silently ignored.
const validate = new Ajv({ allErrors: true, strict: true }).compile(SCENE_SCHEMA);

/** What the schema finds wrong with a scene file (its text or parsed value): `path message` per error, none when it validates. */
export function schemaErrors(scene: unknown): string[] {
  const value = typeof scene === 'string' ? JSON.parse(scene) : scene;
  return validate(value) ? [] : (validate.errors ?? []).map((error) => `${error.instancePath || '/'} ${error.message}`);
}
