/**
 * A .zip of a few files: what the web-editor page offers as the ready
 * folder. Each entry is a local header, its bytes deflated (Node's own zlib,
 * the zip format's method 8) and a central directory entry, with the CRC-32
 * of its bytes. A fixed date: the same files give the same bytes, build after
 * build.
 *
 *   writeFileSync('folder.zip', zip([{ name: 'folder/index.html', data: Buffer.from(html) }]));
 */
import { deflateRawSync } from 'node:zlib';

/** CRC-32 (the zip one: polynomial 0xEDB88320), by a table of the 256 byte values. */
const CRC_TABLE = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});

export function crc32(bytes) {
  let c = 0xffffffff;
  for (const byte of bytes) c = CRC_TABLE[(c ^ byte) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/** 1 January 2020, 00:00, in the format's DOS date and time. */
const DOS_DATE = ((2020 - 1980) << 9) | (1 << 5) | 1, DOS_TIME = 0;
const UTF8_NAMES = 0x0800; // general-purpose flag: names are UTF-8

/**
 * @param {{ name: string, data: Buffer }[]} files paths inside the zip ('/' between folders)
 * @returns {Buffer}
 */
export function zip(files) {
  const locals = [], centrals = [];
  let offset = 0;
  for (const { name, data } of files) {
    const path = Buffer.from(name, 'utf8');
    const crc = crc32(data);
    const packed = deflateRawSync(data, { level: 9 });
    const local = Buffer.alloc(30);
    local.writeUInt32LE(0x04034b50, 0); // local file header
    local.writeUInt16LE(20, 4);          // version needed: 2.0 (deflate)
    local.writeUInt16LE(UTF8_NAMES, 6);
    local.writeUInt16LE(8, 8);           // method: deflate
    local.writeUInt16LE(DOS_TIME, 10);
    local.writeUInt16LE(DOS_DATE, 12);
    local.writeUInt32LE(crc, 14);
    local.writeUInt32LE(packed.length, 18); // compressed size
    local.writeUInt32LE(data.length, 22); // size
    local.writeUInt16LE(path.length, 26);
    local.writeUInt16LE(0, 28);           // no extra field
    locals.push(local, path, packed);

    const central = Buffer.alloc(46);
    central.writeUInt32LE(0x02014b50, 0); // central directory header
    central.writeUInt16LE(20, 4);          // made by: 2.0
    local.copy(central, 6, 4, 30);         // version needed … name length: as in the local header
    // 32 comment length, 34 disk, 36 internal attributes, 38 external attributes: all 0
    central.writeUInt32LE(offset, 42);
    centrals.push(central, path);
    offset += local.length + path.length + packed.length;
  }
  const directory = Buffer.concat(centrals);
  const end = Buffer.alloc(22);
  end.writeUInt32LE(0x06054b50, 0); // end of central directory
  end.writeUInt16LE(files.length, 8);
  end.writeUInt16LE(files.length, 10);
  end.writeUInt32LE(directory.length, 12);
  end.writeUInt32LE(offset, 16);
  return Buffer.concat([...locals, directory, end]);
}
