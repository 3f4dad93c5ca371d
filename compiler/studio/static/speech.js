// The microphone button (issue #18): records one utterance while it is on and streams it: every
// `chunkSeconds` the audio so far goes to `onChunk` as 16-bit mono PCM at the server's rate, base64
// (the page sends it with `hear_chunk`); stop() gives the rest for the `hear` request
// (cnlmc.studio.speech).
// The browser's own echo cancellation, noise suppression and gain control are off: the recogniser
// has its own noise floor and wants the voice as it is.

export class Microphone {
  constructor(rate, maxSeconds, chunkSeconds = 0.5) {
    this.rate = rate;
    this.maxSeconds = maxSeconds;
    this.chunkSeconds = chunkSeconds;
    this.recording = false;
    this.onLimit = null; // called once when an utterance reaches maxSeconds
    this.onChunk = null; // called with each streamed part (base64 PCM at `rate`)
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
    this.pending = []; // input blocks not yet streamed
    this.pendingLength = 0;
    this.length = 0; // input samples taken (at most maxSeconds of them)
    this.resampler = new Resampler(this.context.sampleRate, this.rate);
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
    const limit = Math.floor(this.context.sampleRate * this.maxSeconds);
    // blocks come 4096 samples at a time: cut at the limit the server holds the page to
    const kept = samples.subarray(0, Math.max(0, limit - this.length));
    this.pending.push(new Float32Array(kept));
    this.pendingLength += kept.length;
    this.length += kept.length;
    if (this.pendingLength >= this.context.sampleRate * this.chunkSeconds && this.onChunk) {
      this.onChunk(this.flush());
    }
    if (this.length >= limit && this.onLimit) this.onLimit();
  }

  // The input not yet streamed, resampled to `rate`, as base64 PCM.
  flush() {
    const samples = new Float32Array(this.pendingLength);
    let at = 0;
    for (const block of this.pending) {
      samples.set(block, at);
      at += block.length;
    }
    this.pending = [];
    this.pendingLength = 0;
    return toBase64(toPcm16(this.resampler.next(samples)));
  }

  // The rest of the utterance (what no chunk carried), as base64 PCM at `rate`; the microphone is released.
  stop() {
    this.recording = false;
    this.processor.disconnect();
    this.source.disconnect();
    this.release();
    return this.flush();
  }
}

// A resampler fed block by block that gives exactly what `resample` gives for the whole recording:
// output sample i is the mean of input samples [floor(i r), floor((i + 1) r)) counted from the start
// of the utterance (r = inputRate / outputRate); input an interval still needs waits for the next block.
export class Resampler {
  constructor(inputRate, outputRate) {
    this.ratio = inputRate / outputRate;
    this.buffer = new Float32Array(0);
    this.start = 0; // the utterance's index of buffer[0]
    this.produced = 0; // output samples given so far
  }

  next(block) {
    const buffer = new Float32Array(this.buffer.length + block.length);
    buffer.set(this.buffer, 0);
    buffer.set(block, this.buffer.length);
    const end = this.start + buffer.length;
    const out = [];
    for (let i = this.produced; Math.floor((i + 1) * this.ratio) <= end; i += 1) {
      const first = Math.floor(i * this.ratio);
      const last = Math.max(first + 1, Math.floor((i + 1) * this.ratio));
      let sum = 0;
      for (let j = first; j < last; j += 1) sum += buffer[j - this.start];
      out.push(sum / (last - first));
    }
    this.produced += out.length;
    const keep = Math.floor(this.produced * this.ratio) - this.start;
    this.buffer = buffer.slice(keep);
    this.start += keep;
    return Float32Array.from(out);
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
