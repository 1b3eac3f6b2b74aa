/** Saving and loading scene files: download, file picker, drag-and-drop, and the copy kept across reloads. */

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

/** Calls `onText` with the text of a file dropped anywhere on `target`. */
export function acceptDroppedFiles(target: HTMLElement, onText: (text: string, name: string) => void): void {
  target.addEventListener('dragover', (event) => {
    event.preventDefault();
    if (event.dataTransfer) event.dataTransfer.dropEffect = 'copy';
  });
  target.addEventListener('drop', (event) => {
    event.preventDefault();
    const file = event.dataTransfer?.files[0];
    if (file) void file.text().then((text) => onText(text, file.name));
  });
}

/** The scene kept by the last visit, or null. */
export function storedScene(): string | null {
  try {
    return localStorage.getItem(STORAGE_KEY);
  } catch {
    return null; // Storage can be disabled (private modes, file://): the page still works.
  }
}

/** Keeps `text` for the next visit. */
export function storeScene(text: string): void {
  try {
    localStorage.setItem(STORAGE_KEY, text);
  } catch (error) {
    console.warn('playground: the scene could not be kept across reloads:', error);
  }
}
