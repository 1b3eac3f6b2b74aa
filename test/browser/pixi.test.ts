import { describeExample } from './exampleSuite';

describeExample('PixiJS example', 'pixi/');
