/** The diagrams' palette and type, chosen to read from the back of a room. */
export const INK = '#1d2433';
export const MUTED = '#6b7280';
export const FAINT = '#d7dbe3';
export const PAPER = '#ffffff';
export const RAY = '#c2185b';
export const NORMAL = '#0b8a3e';
export const LIT = '#e0a000';
export const SHADOW = '#d62828';
export const CONSTRUCT = '#1f5fbf';
// No spaces: p5 1.x puts a font name with a space in quotes, and the quoted
// list is no font at all (the text falls back to 10 px). system-ui is Segoe UI on Windows.
export const FONT = 'system-ui,-apple-system,Roboto,sans-serif';
export const SIZE = 14;
