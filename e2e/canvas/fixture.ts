import { physicalApi } from './fixture-api.ts';

physicalApi.define();
window.physical = physicalApi;
document.documentElement.dataset['ready'] = 'true';
