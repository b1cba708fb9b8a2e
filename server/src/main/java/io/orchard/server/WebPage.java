package io.orchard.server;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.ServiceLoader;

/** Finds the browser viewer on the class path and starts it, or says why there is none. */
final class WebPage {

    private WebPage() {}

    static WebFrontEnd.Serving serve(InetSocketAddress http, InetSocketAddress game) throws IOException {
        WebFrontEnd front = ServiceLoader.load(WebFrontEnd.class, WebPage.class.getClassLoader()).findFirst()
                .orElseThrow(() -> new IOException("cannot serve the browser viewer on port " + http.getPort()
                        + ": the web module (io.orchard:web) is not on the class path (expected it beside the"
                        + " server, as ./orchard has it)"));
        return front.serve(http, game);
    }
}
