/**
 * The browser viewer: the HTTP side that serves the three.js page (its own files only, with a
 * Content-Security-Policy) and the WebSocket that relays the page's protocol lines to the game
 * server, so that a browser is a viewer like any other. The server finds it through
 * {@link io.orchard.server.WebFrontEnd} when asked for an HTTP port.
 */
package io.orchard.web;
