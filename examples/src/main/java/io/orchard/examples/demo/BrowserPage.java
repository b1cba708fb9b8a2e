package io.orchard.examples.demo;

import java.awt.Desktop;
import java.awt.GraphicsEnvironment;
import java.io.IOException;
import java.net.URI;

/** Opens the browser viewer's page in the desktop's browser, where there is one; else nothing. */
final class BrowserPage {

    private BrowserPage() {}

    static void open(String page, boolean headless) {
        if (headless || GraphicsEnvironment.isHeadless() || !Desktop.isDesktopSupported()
                || !Desktop.getDesktop().isSupported(Desktop.Action.BROWSE)) {
            return;
        }
        try {
            Desktop.getDesktop().browse(URI.create(page));
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            // The address is printed: a person opens it by hand.
        }
    }
}
