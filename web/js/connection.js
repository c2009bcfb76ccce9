// One WebSocket to the server: JSON text frames out, decoded messages in (protocol.js). Calls
// onOpen(), onMessage(message, localS) and onClose(sentence, code) as they happen; a frame that
// fails to decode is counted, reported on the console and skipped.

import { decodeServer } from './protocol.js';
import { closeSentence } from './plain_words.js';

export class Connection {
  constructor(url, { onOpen, onMessage, onClose }) {
    this.url = url;
    this.badFrames = 0;
    this.lastBadFrame = '';
    this.closed = false;
    this.onClose = onClose;
    try {
      this.ws = new WebSocket(url);
    } catch (e) {
      this.ws = null;
      queueMicrotask(() => this.finish(`Cannot connect to ${url}: ${e.message}`, 0));
      return;
    }
    this.ws.onopen = () => onOpen();
    this.ws.onmessage = (event) => {
      const localS = performance.now() / 1000;
      const decoded = decodeServer(event.data);
      if (decoded.error) {
        this.badFrames += 1;
        this.lastBadFrame = decoded.error;
        // A server that breaks the protocol is worth a line in the console; the page goes on.
        console.error(`carrom: ignored a message from the server (${decoded.error})`);
        return;
      }
      onMessage(decoded.message, localS);
    };
    this.ws.onclose = (event) => this.finish(closeSentence(event.code, event.reason), event.code);
    this.ws.onerror = () => {}; // onclose follows with the code
  }

  finish(sentence, code) {
    if (this.closed) return;
    this.closed = true;
    this.onClose(sentence, code);
  }

  isOpen() {
    return this.ws !== null && this.ws.readyState === WebSocket.OPEN && !this.closed;
  }

  send(message) {
    if (!this.isOpen()) return false;
    this.ws.send(JSON.stringify(message));
    return true;
  }

  // Closes without reporting (the caller already knows).
  close() {
    this.closed = true;
    if (this.ws) {
      this.ws.onclose = null;
      this.ws.onmessage = null;
      this.ws.close(1000);
    }
  }
}
