/**
 * Saving and loading scene files: download, file picker, drag-and-drop, and the copy kept across
 * reloads; and image files, picked or dropped, for tracing into hulls.
 */

const STORAGE_KEY = 'penumbra-gl/playground/scene';

/** Offers `text` as a download named `fileName`. */
export function downloadText(text: string, fileName: string): void {
  const url = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.click();
  // The click has started the download by the time the next task runs.
  setTimeout(() => URL.revokeObjectURL(url), 0);
}

/** Opens the file picker; calls `onText` with the chosen file's text. */
export function pickTextFile(onText: (text: string, name: string) => void): void {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = '.json,application/json';
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (file) void file.text().then((text) => onText(text, file.name));
  });
  input.click();
}

/** What to do with a dropped file: a scene file's text, or an image file and the page point (CSS pixels) it was dropped at. */
interface DropHandlers {
  text(text: string, name: string): void;
  image(file: File, clientX: number, clientY: number): void;
}

/** Whether a file is an image by its type or, failing that, its name (some systems give no type). */
function isImageFile(file: File): boolean {
  return file.type.startsWith('image/') || (file.type === '' && /\.(png|jpe?g|gif|webp|avif|bmp)$/i.test(file.name));
}

/** Hands a file dropped anywhere on `target` to `handlers`: images as files, anything else as scene text. */
export function acceptDroppedFiles(target: HTMLElement, handlers: DropHandlers): void {
  target.addEventListener('dragover', (event) => {
    event.preventDefault();
    if (event.dataTransfer) event.dataTransfer.dropEffect = 'copy';
  });
  target.addEventListener('drop', (event) => {
    event.preventDefault();
    const file = event.dataTransfer?.files[0];
    if (!file) return;
    if (isImageFile(file)) handlers.image(file, event.clientX, event.clientY);
    else void file.text().then((text) => handlers.text(text, file.name));
  });
}

/** Opens the file picker for an image; calls `onFile` with the chosen file. */
export function pickImageFile(onFile: (file: File) => void): void {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = 'image/*';
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (file) onFile(file);
  });
  input.click();
}

/** The scene file kept by the last visit (its application data says which art draws it), or null. */
export function storedScene(): string | null {
  try {
    return localStorage.getItem(STORAGE_KEY);
  } catch {
    return null; // Storage can be disabled (private modes, file://): the page still works.
  }
}

/** Keeps scene file `text` for the next visit. */
export function storeScene(text: string): void {
  try {
    localStorage.setItem(STORAGE_KEY, text);
  } catch (error) {
    console.warn('playground: the scene could not be kept across reloads:', error);
  }
}
