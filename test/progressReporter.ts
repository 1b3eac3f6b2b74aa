// Progress for logs without a terminal (CI, `npm test | tee`): a line when a test file starts and
// one when it ends, numbered among the run's files, with its counts and time. Some files spend
// minutes in their set-up (packing, building, launching Chromium) before their first test reports,
// so the start line says which one is busy. Used beside the verbose reporter (vitest.config.ts).
import type { Reporter, TestModule, TestSpecification } from 'vitest/node';

export default class ProgressReporter implements Reporter {
  private total = 0;
  private started = 0;
  private readonly numbers = new Map<string, number>();

  onTestRunStart(specifications: ReadonlyArray<TestSpecification>): void {
    this.total = specifications.length;
    this.started = 0;
    this.numbers.clear();
  }

  onTestModuleStart(testModule: TestModule): void {
    this.numbers.set(testModule.moduleId, ++this.started);
    this.print(`▶ [${this.started}/${this.total}] ${testModule.relativeModuleId} started`);
  }

  onTestModuleEnd(testModule: TestModule): void {
    const counts = { passed: 0, failed: 0, skipped: 0 };
    for (const test of testModule.children.allTests()) {
      const state = test.result().state;
      if (state === 'passed' || state === 'failed' || state === 'skipped') counts[state]++;
    }
    const mark = counts.failed > 0 || testModule.state() === 'failed' ? '✗' : '✓';
    const seconds = (testModule.diagnostic().duration / 1000).toFixed(1);
    const number = this.numbers.get(testModule.moduleId) ?? this.started;
    this.print(`${mark} [${number}/${this.total}] ${testModule.relativeModuleId}: ${counts.passed} passed, ${counts.failed} failed, ${counts.skipped} skipped in ${seconds} s`);
  }

  private print(line: string): void {
    process.stdout.write(`${line}\n`);
  }
}
