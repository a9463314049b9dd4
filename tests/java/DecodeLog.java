// DecodeLog LOG TYPES_JAR [CHANNEL_REGEX=TYPE ...]
//
// Decodes every event of an LCM log the way lcm-spy does: it loads every class
// of the types jar, maps each class's static LCM_FINGERPRINT to it, and picks
// the class of an event by the event's first 8 bytes (the big-endian
// fingerprint). Each event is decoded with the class's DataInput constructor,
// must consume all its bytes, and must re-encode to the same bytes.
//
// Fails (exit 1, one line "FAIL: ...") when two classes share a fingerprint,
// when an event on a DREAM_* channel cannot be decoded, or when a channel
// matching one of the CHANNEL_REGEX=TYPE arguments carries another type.
// Prints per channel the type and the number of events.
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.File;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.Arrays;
import java.util.Enumeration;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.TreeMap;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

import lcm.logging.Log;

public class DecodeLog {
  private static class Failure extends Exception {
    private static final long serialVersionUID = 1L;

    Failure(String message) { super(message); }
  }

  /** Fingerprint -> class, from every class in the jar that has a static long LCM_FINGERPRINT. */
  static Map<Long, Class<?>> typesByFingerprint(String jarPath) throws Exception {
    Map<Long, Class<?>> types = new HashMap<>();
    URLClassLoader loader = new URLClassLoader(new URL[] {new File(jarPath).toURI().toURL()},
                                               DecodeLog.class.getClassLoader());
    try (JarFile jar = new JarFile(jarPath)) {
      Enumeration<JarEntry> entries = jar.entries();
      while (entries.hasMoreElements()) {
        String name = entries.nextElement().getName();
        if (!name.endsWith(".class") || name.contains("$")) continue;
        Class<?> type = loader.loadClass(name.substring(0, name.length() - 6).replace('/', '.'));
        Field field;
        try {
          field = type.getField("LCM_FINGERPRINT");
        } catch (NoSuchFieldException e) {
          continue;
        }
        if (!Modifier.isStatic(field.getModifiers()) || field.getType() != long.class) continue;
        long fingerprint = field.getLong(null);
        Class<?> previous = types.put(fingerprint, type);
        if (previous != null) {
          throw new Failure(String.format(
              "%s and %s share the fingerprint %016x: lcm-spy cannot tell them apart", previous.getName(),
              type.getName(), fingerprint));
        }
      }
    }
    if (types.isEmpty()) throw new Failure(jarPath + " holds no LCM types (no class with LCM_FINGERPRINT)");
    return types;
  }

  /** Decodes data as type; checks that every byte is used and that it re-encodes to the same bytes. */
  static void decode(Class<?> type, byte[] data) throws Exception {
    ByteArrayInputStream bytes = new ByteArrayInputStream(data);
    Constructor<?> constructor = type.getConstructor(java.io.DataInput.class);
    Object message;
    try {
      message = constructor.newInstance(new DataInputStream(bytes));
    } catch (InvocationTargetException e) {
      throw new Failure("decoding as " + type.getName() + " threw " + e.getCause());
    }
    if (bytes.available() != 0) {
      throw new Failure(bytes.available() + " of " + data.length + " bytes left over after decoding as "
                        + type.getName());
    }
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    Method encode = type.getMethod("encode", java.io.DataOutput.class);
    encode.invoke(message, new DataOutputStream(out));
    if (!Arrays.equals(out.toByteArray(), data)) {
      throw new Failure("re-encoding as " + type.getName() + " gives different bytes");
    }
  }

  static long fingerprintOf(byte[] data) {
    long fingerprint = 0;
    for (int i = 0; i < 8; ++i) fingerprint = (fingerprint << 8) | (data[i] & 0xff);
    return fingerprint;
  }

  static void run(String[] args) throws Exception {
    if (args.length < 2) throw new Failure("usage: DecodeLog LOG TYPES_JAR [CHANNEL_REGEX=TYPE ...]");
    Map<Long, Class<?>> types = typesByFingerprint(args[1]);
    Map<String, String> expected = new LinkedHashMap<>();
    for (int i = 2; i < args.length; ++i) {
      int eq = args[i].indexOf('=');
      if (eq <= 0) throw new Failure("expected CHANNEL_REGEX=TYPE, got " + args[i]);
      expected.put(args[i].substring(0, eq), args[i].substring(eq + 1));
    }

    Map<String, String> typeOfChannel = new TreeMap<>();
    Map<String, Integer> countOfChannel = new TreeMap<>();
    Log log = new Log(args[0], "r");
    long events = 0;
    try {
      while (true) {
        Log.Event event;
        try {
          event = log.readNext();
        } catch (EOFException end) {
          break;
        }
        ++events;
        String channel = event.channel;
        String where = args[0] + ": event " + (events - 1) + " on " + channel;
        Class<?> type = event.data.length >= 8 ? types.get(fingerprintOf(event.data)) : null;
        if (type == null) {
          if (channel.startsWith("DREAM_")) {
            throw new Failure(where + ": no type in the jar has fingerprint "
                              + (event.data.length >= 8 ? String.format("%016x", fingerprintOf(event.data))
                                                        : "(fewer than 8 bytes)"));
          }
          typeOfChannel.putIfAbsent(channel, "(unknown type)");
        } else {
          try {
            decode(type, event.data);
          } catch (Failure e) {
            throw new Failure(where + ": " + e.getMessage());
          }
          String previous = typeOfChannel.put(channel, type.getName());
          if (previous != null && !previous.equals(type.getName())) {
            throw new Failure(channel + " carries two types: " + previous + " and " + type.getName());
          }
        }
        countOfChannel.merge(channel, 1, Integer::sum);
      }
    } finally {
      log.close();
    }

    for (Map.Entry<String, String> want : expected.entrySet()) {
      boolean seen = false;
      for (Map.Entry<String, String> got : typeOfChannel.entrySet()) {
        if (!got.getKey().matches(want.getKey())) continue;
        seen = true;
        if (!got.getValue().equals(want.getValue())) {
          throw new Failure(got.getKey() + " carries " + got.getValue() + ", expected " + want.getValue());
        }
      }
      if (!seen) throw new Failure("no channel of the log matches " + want.getKey());
    }
    for (Map.Entry<String, String> entry : typeOfChannel.entrySet()) {
      System.out.println(entry.getKey() + " " + entry.getValue() + " " + countOfChannel.get(entry.getKey()));
    }
    System.out.println("ok: decoded " + events + " events with " + types.size() + " types from " + args[1]);
  }

  public static void main(String[] args) {
    try {
      run(args);
    } catch (Failure e) {
      System.out.println("FAIL: " + e.getMessage());
      System.exit(1);
    } catch (Exception e) {
      System.out.println("FAIL: " + e);
      System.exit(1);
    }
  }
}
