/**
 * Event sounds: a short soft tone when something happens (a wall hit, a collision, a run ending).
 * Off by default; the learner turns them on with the toggle in the top bar.
 */
const KEY = 'newton.sound';
let enabled = readSaved();
let audio: AudioContext | null = null;
let lastAt = 0;
const listeners = new Set<() => void>();

function readSaved(): boolean {
  try {
    return globalThis.localStorage?.getItem(KEY) === 'on';
  } catch {
    return false;
  }
}

export function soundEnabled(): boolean {
  return enabled;
}

export function setSoundEnabled(value: boolean): void {
  enabled = value;
  try {
    localStorage.setItem(KEY, value ? 'on' : 'off');
  } catch {
    // Not saved: the choice lasts for this visit.
  }
  for (const listener of listeners) listener();
}

export function onSoundChange(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/** Number of tones played (read by the browser tests). */
export let tonesPlayed = 0;

/** Plays a 60 ms tone if sound is on (at most one every 120 ms: a burst stays one sound). */
export function playEventTone(frequency = 660): void {
  if (!enabled || typeof AudioContext === 'undefined') return;
  const now = performance.now();
  if (now - lastAt < 120) return;
  lastAt = now;
  audio ??= new AudioContext();
  const oscillator = audio.createOscillator();
  const gain = audio.createGain();
  oscillator.frequency.value = frequency;
  gain.gain.setValueAtTime(0.08, audio.currentTime);
  gain.gain.exponentialRampToValueAtTime(0.0001, audio.currentTime + 0.06);
  oscillator.connect(gain).connect(audio.destination);
  oscillator.start();
  oscillator.stop(audio.currentTime + 0.07);
  tonesPlayed++;
  document.documentElement.dataset['tones'] = String(tonesPlayed);
}
