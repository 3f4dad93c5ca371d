// The microphone button (issue #18): records one utterance while it is on, then gives it back as
// 16-bit mono PCM at the server's rate, base64, for the `hear` request (cnlmc.studio.speech).
// The browser's own echo cancellation, noise suppression and gain control are off: the recogniser
// has its own noise floor and wants the voice as it is.

export class Microphone {
  constructor(rate, maxSeconds) {
    this.rate = rate;
    this.maxSeconds = maxSeconds;
    this.recording = false;
    this.onLimit = null; // called once when an utterance reaches maxSeconds
  }

  async start() {
    this.stream = await navigator.mediaDevices.getUserMedia({
      audio: { channelCount: 1, echoCancellation: false, noiseSuppression: false, autoGainControl: false },
    });
    try {
      this.context = new AudioContext();
      this.source = this.context.createMediaStreamSource(this.stream);
      this.processor = this.context.createScriptProcessor(4096, 1, 1);
    } catch (error) {
      this.release(); // the microphone is not left on
      throw error;
    }
    this.chunks = [];
    this.length = 0;
    this.processor.onaudioprocess = (event) => this.collect(event.inputBuffer.getChannelData(0));
    this.source.connect(this.processor);
    this.processor.connect(this.context.destination); // a processor runs only when connected
    this.recording = true;
  }

  release() {
    for (const track of this.stream?.getTracks() || []) track.stop();
    if (this.context && this.context.state !== "closed") this.context.close();
    this.stream = this.context = null;
  }

  collect(samples) {
    if (!this.recording) return;
    this.chunks.push(new Float32Array(samples));
    this.length += samples.length;
    if (this.length >= this.context.sampleRate * this.maxSeconds && this.onLimit) this.onLimit();
  }

  // The utterance recorded since start(), as base64 PCM at `rate`; the microphone is released.
  stop() {
    this.recording = false;
    const inputRate = this.context.sampleRate;
    this.processor.disconnect();
    this.source.disconnect();
    this.release();
    // blocks come 4096 samples at a time: cut at the limit the server holds the page to
    const samples = new Float32Array(Math.min(this.length, Math.floor(inputRate * this.maxSeconds)));
    let at = 0;
    for (const chunk of this.chunks) {
      if (at >= samples.length) break;
      const part = chunk.subarray(0, samples.length - at);
      samples.set(part, at);
      at += part.length;
    }
    return toBase64(toPcm16(resample(samples, inputRate, this.rate)));
  }
}

// The samples at `outputRate`: each output sample the mean of the input samples of its interval (a
// box low-pass before the decimation, enough for speech under 8 kHz).
export function resample(samples, inputRate, outputRate) {
  const ratio = inputRate / outputRate;
  const out = new Float32Array(Math.floor(samples.length / ratio));
  for (let i = 0; i < out.length; i += 1) {
    const first = Math.floor(i * ratio);
    const last = Math.max(first + 1, Math.floor((i + 1) * ratio));
    let sum = 0;
    for (let j = first; j < last; j += 1) sum += samples[j];
    out[i] = sum / (last - first);
  }
  return out;
}

function toPcm16(samples) {
  const bytes = new Uint8Array(samples.length * 2);
  const view = new DataView(bytes.buffer);
  for (let i = 0; i < samples.length; i += 1) {
    const clipped = Math.max(-1, Math.min(1, samples[i]));
    view.setInt16(2 * i, Math.round(clipped * 32767), true);
  }
  return bytes;
}

function toBase64(bytes) {
  let binary = "";
  const step = 0x8000;
  for (let i = 0; i < bytes.length; i += step) binary += String.fromCharCode(...bytes.subarray(i, i + step));
  return btoa(binary);
}
