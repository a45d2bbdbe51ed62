import { workerApi } from './fixture-api.ts';

workerApi.define();
window.physicalWorker = workerApi;
document.documentElement.dataset['ready'] = 'true';
