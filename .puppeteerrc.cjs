// Puppeteer must not download its own Chrome (no internet here); tests launch Debian's Chromium.
module.exports = { skipDownload: true };
