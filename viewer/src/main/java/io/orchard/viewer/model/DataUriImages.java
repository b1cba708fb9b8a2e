package io.orchard.viewer.model;

import com.jme3.texture.Image;
import com.jme3.texture.plugins.AWTLoader;
import io.orchard.viewer.model.ModelException.Kind;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.Base64;
import java.util.Iterator;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import javax.imageio.stream.MemoryCacheImageInputStream;

/**
 * Decodes images embedded in models as base64 {@code data:} URIs, PNG or JPEG only. The image
 * header is read first and the image refused if it is larger than the texture limit, so a small
 * file that claims enormous dimensions (a decompression bomb) is never decoded. Decoding stays
 * in memory: no temporary files, no URLs.
 */
public final class DataUriImages {

    private DataUriImages() {
    }

    /** The bytes a {@code data:} URI carries, or null if the URI is not a base64 data URI. */
    public static byte[] bytes(String uri, String where) throws ModelException {
        if (!isDataUri(uri)) {
            return null;
        }
        int comma = uri.indexOf(',');
        if (comma < 0) {
            throw new ModelException(Kind.BAD_VALUE, where + ": data: URI has no ',' before its"
                    + " data: '" + abbreviate(uri) + "'");
        }
        String header = uri.substring(5, comma).toLowerCase(Locale.ROOT);
        if (!header.endsWith(";base64")) {
            throw new ModelException(Kind.UNSUPPORTED, where + ": only base64 data: URIs are"
                    + " read, not '" + abbreviate(uri.substring(0, comma + 1)) + "'");
        }
        try {
            // Long URIs are often wrapped across lines; white space is not part of the data.
            return Base64.getDecoder().decode(uri.substring(comma + 1).replaceAll("\\s+", ""));
        } catch (IllegalArgumentException e) {
            throw new ModelException(Kind.BAD_VALUE, where + ": data: URI is not valid base64 ("
                    + e.getMessage() + ")", e);
        }
    }

    /** Whether {@code uri} starts with {@code data:}, in any case. */
    public static boolean isDataUri(String uri) {
        return uri.regionMatches(true, 0, "data:", 0, 5);
    }

    /** Width and height from the image header, without decoding the pixels. */
    public static int[] size(byte[] image, String where) throws ModelException {
        ImageReader reader = reader(image, where);
        try {
            return new int[] {reader.getWidth(0), reader.getHeight(0)};
        } catch (IOException | RuntimeException e) {
            throw new ModelException(Kind.BAD_VALUE, where + ": embedded image header cannot be"
                    + " read (" + e.getMessage() + ")", e);
        } finally {
            reader.dispose();
        }
    }

    /** Checks the size against {@code maxSize}, then decodes to a jME image, rows bottom-up. */
    public static Image decode(byte[] image, int maxSize, String where) throws ModelException {
        ImageReader reader = reader(image, where);
        try {
            int width = reader.getWidth(0);
            int height = reader.getHeight(0);
            checkSize(width, height, maxSize, where);
            BufferedImage pixels = reader.read(0);
            return new AWTLoader().load(pixels, true);
        } catch (IOException | RuntimeException e) {
            throw new ModelException(Kind.BAD_VALUE, where + ": embedded image cannot be decoded"
                    + " (" + e.getMessage() + ")", e);
        } finally {
            reader.dispose();
        }
    }

    /** Refuses an image wider or taller than {@code maxSize} pixels, before its pixels are decoded. */
    public static void checkSize(int width, int height, int maxSize, String where)
            throws ModelException {
        if (width > maxSize || height > maxSize) {
            throw new ModelException(Kind.TOO_LARGE, where + ": embedded image of " + width + "x"
                    + height + " pixels exceeds the limit of " + maxSize + " pixels a side");
        }
    }

    private static ImageReader reader(byte[] image, String where) throws ModelException {
        if (!isPng(image) && !isJpeg(image)) {
            throw new ModelException(Kind.UNSUPPORTED, where + ": embedded image is neither PNG"
                    + " nor JPEG");
        }
        ImageInputStream input = new MemoryCacheImageInputStream(new ByteArrayInputStream(image));
        Iterator<ImageReader> readers = ImageIO.getImageReaders(input);
        if (!readers.hasNext()) {
            throw new ModelException(Kind.UNSUPPORTED, where + ": no decoder for the embedded"
                    + " image");
        }
        ImageReader reader = readers.next();
        reader.setInput(input, true, true);
        return reader;
    }

    private static boolean isPng(byte[] b) {
        return b.length >= 8 && (b[0] & 0xff) == 0x89 && b[1] == 'P' && b[2] == 'N'
                && b[3] == 'G';
    }

    private static boolean isJpeg(byte[] b) {
        return b.length >= 3 && (b[0] & 0xff) == 0xff && (b[1] & 0xff) == 0xd8
                && (b[2] & 0xff) == 0xff;
    }

    private static String abbreviate(String text) {
        return text.length() <= 40 ? text : text.substring(0, 37) + "...";
    }
}
