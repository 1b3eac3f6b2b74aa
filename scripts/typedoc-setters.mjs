// @ts-check
// A TypeDoc plugin: one comment on a getter documents the getter/setter pair, as readers of the
// source see it; TypeDoc would otherwise report every setter as undocumented.
import { Converter, ReflectionKind } from 'typedoc';

/** @param {import('typedoc').Application} app */
export function load(app) {
  app.converter.on(Converter.EVENT_RESOLVE_BEGIN, (context) => {
    for (const accessor of context.project.getReflectionsByKind(ReflectionKind.Accessor)) {
      if (!(accessor instanceof Object) || !('setSignature' in accessor)) continue;
      const { getSignature, setSignature } = /** @type {import('typedoc').DeclarationReflection} */ (accessor);
      if (setSignature && !setSignature.comment && getSignature?.comment) setSignature.comment = getSignature.comment.clone();
    }
  });
}
