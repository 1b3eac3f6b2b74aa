import { expect } from 'vitest';

/** The message of the error `act` throws, checking its class; fails when it throws nothing. */
export function messageOf(act: () => unknown, type: ErrorConstructor): string {
  try {
    act();
  } catch (error) {
    expect(error).toBeInstanceOf(type);
    return (error as Error).message;
  }
  throw new Error('expected an error');
}
