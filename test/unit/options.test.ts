import * as source from '../../src/index';
import { testLibrary } from './optionMessages';

testLibrary('src', () => source);
