import { describeExample } from './exampleSuite';

describeExample('Phaser example', 'phaser/');
